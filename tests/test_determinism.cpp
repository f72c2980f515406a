// labels: physics;engine
// The same scene and inputs give bit-identical states, whatever the caller's
// frame rate, after a snapshot and restore, and when a recorded drag replays.
#include "jl/engine/kept_evaluation.h"
#include "jl/engine/motion.h"
#include "jl/sim/recording.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <cmath>

using namespace jl;
using namespace jl::test;

namespace {

const char* kClassic = "examples/classic.yaml";

std::uint64_t hashAfter(double until, double frame) {
    auto sim = simulateFile(kClassic);
    for (double t = frame; t < until; t += frame) sim->advanceTo(t);
    sim->advanceTo(until);
    return sim->stateHash();
}

}  // namespace

class DeterminismTest : public QObject {
    Q_OBJECT
private slots:
    void hashDoesNotDependOnFrameInterval() {
        const std::uint64_t once = hashAfter(1.2, 1.2);
        QCOMPARE(hashAfter(1.2, 1.0 / 60), once);
        QCOMPARE(hashAfter(1.2, 1.0 / 24), once);
        QCOMPARE(hashAfter(1.2, 0.0137), once);
    }

    void hashChangesWhenTheStateDoes() { QVERIFY(hashAfter(1.2, 0.1) != hashAfter(1.0, 0.1)); }

    void restoreCarriesOnBitIdentically() {
        auto sim = simulateFile(kClassic);
        sim->advanceTo(0.55);  // mid-cascade
        const auto snap = sim->snapshot();
        sim->advanceTo(1.3);
        const std::uint64_t straight = sim->stateHash();
        sim->restore(*snap);
        sim->advanceTo(1.3);
        QCOMPARE(sim->stateHash(), straight);
    }

    // The halved automatic step is part of the state, and so is the books'
    // scale that decides it: falling-chain.yaml halves its step within a
    // few seconds past its duration (RK4's error at 1 ms passes a
    // thousandth of the largest energy that has flowed; near 7 s), and a
    // fresh simulation restored to a snapshot taken after that carries on
    // with the halved step, bit for bit (the timeline rebuilds dropped
    // frames that way).
    void restoreIntoAFreshSimulationKeepsAHalvedStep() {
        auto sim = simulateFile("examples/falling-chain.yaml");
        QVERIFY(sim);
        while (sim->frame().solver.stepHalvings == 0 && sim->time() < 12.0) QVERIFY(sim->advanceTo(sim->time() + 0.1));
        QVERIFY(sim->frame().solver.stepHalvings >= 1);
        const double halved = sim->time();
        const auto snap = sim->snapshot();
        QVERIFY(sim->advanceTo(halved + 0.9));
        const std::uint64_t straight = sim->stateHash();
        auto fresh = simulateFile("examples/falling-chain.yaml");
        QVERIFY(fresh);
        fresh->restore(*snap);
        QVERIFY(fresh->advanceTo(halved + 0.9));
        QCOMPARE(fresh->stateHash(), straight);
        QCOMPARE(fresh->frame().solver.stepHalvings, sim->frame().solver.stepHalvings);
    }

    // A step's first stage taken from the previous step's end evaluation
    // (KeptEvaluation) is the same evaluation: the motion and the books come
    // out bit for bit as when every stage is evaluated, one evaluation a
    // step cheaper, for every explicit method (the adaptive one too, whose
    // rejected trials also share their first stage).
    void theFirstStageTakenFromTheLastStepsEndChangesNothing() {
        auto sim = simulateFile(kClassic);
        QVERIFY(sim);
        sim->advanceTo(0.55);  // mid-cascade: the hand turning, blocks swinging
        for (Integrator kind :
             {Integrator::ExplicitEuler, Integrator::SymplecticEuler, Integrator::RK4, Integrator::DormandPrince45}) {
            struct Run {
                World w;
                Dynamics d;
                Stepper s;
                Ledger ledger;
                KeptEvaluation kept;
            };
            Run plain{sim->world(), {}, Stepper(kind, 1e-7), {}, {}};
            Run reusing{sim->world(), {}, Stepper(kind, 1e-7), {}, {}};
            const double h = kind == Integrator::ExplicitEuler || kind == Integrator::SymplecticEuler ? 1e-4 : 1e-3;
            double tPlain = 0.55, tReusing = 0.55;
            const int steps = 100;
            for (int i = 0; i < steps; ++i) {
                for (Run* r : {&plain, &reusing}) {
                    double& t = r == &plain ? tPlain : tReusing;
                    const Powers* atStart = r == &reusing ? r->kept.recall(r->w, r->d, t) : nullptr;
                    QCOMPARE(atStart != nullptr, r == &reusing && i > 0);
                    const MotionStep m = advanceAndProject(r->w, r->d, r->s, t, h, r->ledger, 1e-10, false, atStart);
                    QVERIFY(m.ok());
                    t += m.step.taken;
                    // The end state evaluated, as the simulation does for its event functions.
                    {
                        const Powers p = r->d.evaluate(r->w, t);
                        r->kept.keep(r->w, r->d, t, p);
                    }
                }
            }
            QCOMPARE(tReusing, tPlain);
            QVERIFY(reusing.w.q == plain.w.q);
            QVERIFY(reusing.w.v == plain.w.v);
            QCOMPARE(reusing.ledger.held, plain.ledger.held);
            QCOMPARE(reusing.ledger.damping, plain.ledger.damping);
            QCOMPARE(reusing.d.evaluations(), plain.d.evaluations() - (steps - 1));
        }
    }

    // Recalled only for the very same inputs: time, positions, velocities,
    // gravity, and nothing else of the world changed.
    void aKeptEvaluationIsRecalledOnlyForTheSameInputs() {
        auto sim = simulateFile(kClassic);
        QVERIFY(sim);
        sim->advanceTo(0.3);
        World w = sim->world();
        Dynamics d;
        KeptEvaluation kept;
        const double t = sim->time();
        {
            const Powers p = d.evaluate(w, t);
            kept.keep(w, d, t, p);
        }
        const Eigen::VectorXd a = w.a, lambda = d.pinForces();
        w.a.setZero();
        {
            World other = w;  // the dynamics last evaluated elsewhere
            other.v.array() += 0.5;
            (void)d.evaluate(other, t);
            QVERIFY(d.pinForces() != lambda);
        }
        QVERIFY(kept.recall(w, d, t) != nullptr);
        QVERIFY(w.a == a);  // put back, with the pin forces
        QVERIFY(d.pinForces() == lambda);
        QVERIFY(kept.recall(w, d, std::nextafter(t, 1.0)) == nullptr);
        {
            World moved = w;
            moved.q[4] = std::nextafter(moved.q[4], 1.0);
            QVERIFY(kept.recall(moved, d, t) == nullptr);
        }
        {
            World pushed = w;
            pushed.v[5] += 1e-12;
            QVERIFY(kept.recall(pushed, d, t) == nullptr);
        }
        {
            World heavier = w;
            heavier.gravity.y() -= 0.01;
            QVERIFY(kept.recall(heavier, d, t) == nullptr);
        }
        {
            World dragged = w;
            (void)dragged.editDrags();  // a reference to change them through: the world may have changed
            QVERIFY(kept.recall(dragged, d, t) == nullptr);
        }
        {
            // Reading through a non-const world changes nothing: an
            // evaluation, which reads the contacts, leaves the revision (and
            // every cache keyed on it) as it was.
            World read = w;
            const std::uint64_t revision = read.revision();
            (void)read.contacts(), (void)read.drags(), (void)read.loads();
            (void)Dynamics().evaluate(read, t);
            QCOMPARE(read.revision(), revision);
        }
        {
            // Not with resting contacts: their matrix is not kept.
            World resting = w;
            resting.editContacts().push_back({});
            KeptEvaluation withContacts;
            withContacts.keep(resting, d, t, {});
            QVERIFY(withContacts.recall(resting, d, t) == nullptr);
        }
        {
            World copy = w;  // a copy is the same world
            QVERIFY(kept.recall(copy, d, t) != nullptr);
        }
        kept.forget();
        QVERIFY(kept.recall(w, d, t) == nullptr);
    }

    // A recording (jladder run, the exports) writes numbers only: its frames
    // leave the ribbons out, and the simulation draws them again afterwards.
    void aRecordingsFramesLeaveTheRibbonsOut() {
        auto sim = simulateFile(kClassic);
        QVERIFY(sim);
        QVERIFY(!sim->frame().ribbons.empty());
        struct Count : RecordTarget {
            int frames = 0, withRibbons = 0;
            bool frame(const Frame& f) override {
                ++frames;
                withRibbons += !f.ribbons.empty();
                return true;
            }
            bool event(const Event&) override { return true; }
        } count;
        const Recording r = record(*sim, 0.5, FrameGrid{0, 0.05}, &count);
        QVERIFY(r.complete());
        QCOMPARE(count.frames, 11);
        QCOMPARE(count.withRibbons, 0);
        QVERIFY(!sim->frame().ribbons.empty());
    }

    // A drag during a run is recorded into the scene; running that scene
    // again replays it to the bit, and the drag did change the motion.
    void recordedDragReplaysBitIdentically() {
        auto live = simulateFile(kClassic);
        live->advanceTo(0.6);
        live->beginDrag(4, Vec2(0, 0.02), Vec2(0.1, -0.25));
        live->advanceTo(0.7);
        live->moveDrag(Vec2(0.15, -0.2));
        live->advanceTo(0.85);
        live->endDrag();
        live->advanceTo(1.4);
        QCOMPARE(int(live->scene().drags.size()), 1);
        QVERIFY(live->scene().drags[0].samples.size() == 2);

        auto replay = Simulation::build(live->scene()).simulation;
        QVERIFY(replay);
        replay->advanceTo(1.4);
        QCOMPARE(replay->stateHash(), live->stateHash());

        auto undisturbed = simulateFile(kClassic);
        undisturbed->advanceTo(1.4);
        QVERIFY(undisturbed->stateHash() != live->stateHash());
        const Vec2 a = undisturbed->frame().poses[4].position, b = live->frame().poses[4].position;
        QVERIFY2((a - b).norm() > 1e-3, qPrintable(QString::number((a - b).norm())));
    }

    // A drag while paused (no simulated time between press and release)
    // moves nothing: it leaves no record to replay or save, and the run
    // carries on exactly as if it had not happened.
    void aDragWhileNoTimePassesLeavesNothing() {
        auto sim = simulateFile(kClassic);
        sim->advanceTo(0.6);
        sim->beginDrag(4, Vec2(0, 0.02), Vec2(0.1, -0.25));
        sim->moveDrag(Vec2(0.15, -0.2));
        sim->endDrag();
        QVERIFY(sim->scene().drags.empty());
        QVERIFY(sim->world().drags().empty());
        sim->advanceTo(1.4);
        auto undisturbed = simulateFile(kClassic);
        undisturbed->advanceTo(0.6);
        undisturbed->advanceTo(1.4);
        QCOMPARE(sim->stateHash(), undisturbed->stateHash());
    }
};

QTEST_GUILESS_MAIN(DeterminismTest)
#include "test_determinism.moc"
