// A simulation made and read: built from a scene (simulation_build.cpp),
// stepped (simulation_step.cpp), driven by the script and the user's drags
// (simulation_script.cpp, simulation_drags.cpp); here its frames and picking.
#include "jl/sim/simulation.h"

#include "jl/engine/energy.h"

#include <cmath>
#include <utility>

namespace jl {

Simulation::Simulation(const Scene& scene)
    : scene_(scene),
      stepper_(scene.solver.integrator, scene.solver.tolerance),
      interpolant_(scene.solver.integrator == Integrator::SymplecticEuler ? StepInterpolant::Inside::SymplecticEuler
                                                                          : StepInterpolant::Inside::Quintic) {}

Simulation::Built Simulation::build(const Scene& scene) {
    Built b;
    std::unique_ptr<Simulation> s(new Simulation(scene));
    if (auto error = s->buildWorld()) {
        b.errors.push_back(*error);
        return b;
    }
    b.simulation = std::move(s);
    return b;
}

Frame Simulation::frame() {
    Frame f;
    f.time = t_;
    f.poses.reserve(blocks_.size());
    f.held.reserve(blocks_.size());
    for (PartId p : blocks_) {
        f.poses.push_back(world_.partPose(p));
        f.held.push_back(world_.isHeld(p));
    }
    if (ladder_) {
        f.hinges = ladder_->hingeFrames(world_);
        if (ribbonsInFrames_) f.ribbons = ladder_->ribbons(world_);
        f.blockContacts = ladder_->blockContacts().frames(world_, dynamics_);
    }
    for (const Spring& s : world_.springs())
        f.springs.emplace_back(world_.particlePosition(s.a), world_.particlePosition(s.b));
    const Energy e = energy(world_);
    f.energy.kinetic = e.kinetic;
    f.energy.potential = e.potential;
    f.energy.heldWork = ledger_.held + impactHeldWork_;
    f.energy.userWork = ledger_.user;
    f.energy.dampingLoss = ledger_.damping;
    f.energy.impactLoss = impactLoss_;
    f.energy.initial = initialEnergy_;
    f.solver = stats_;
    f.solver.evaluations = dynamics_.evaluations();
    f.solver.residual = lastResidual_;
    f.solver.pins = int(world_.pins().size());
    f.solver.stillFrom = ladder_ && ladder_->stillFrom() < ladder_->blockCount() ? ladder_->stillFrom() : -1;
    for (int b = 0; b < world_.bodyCount(); ++b)
        if (world_.body(b).alive && !world_.body(b).kinematic) ++f.solver.bodies;
    f.events = std::move(pending_);
    pending_.clear();
    if (const auto& drags = std::as_const(world_).drags(); !drags.empty()) {
        const UserDrag& g = drags.front();
        f.dragging = true;
        f.dragFrom = world_.pointPosition(g.part, g.local);
        f.dragTo = g.target;
    }
    f.failure = failure_;
    return f;
}

std::optional<std::pair<int, Vec2>> Simulation::pick(const Vec2& point) const {
    constexpr double margin = 0.002;  // m: thin blocks stay pickable
    for (int i = blockCount() - 1; i >= 0; --i) {
        const Part& part = world_.part(blockPart(i));
        const Pose pose = world_.partPose(blockPart(i));
        const Vec2 local = rotate(-pose.angle, point - pose.position);
        if (std::abs(local.x()) <= part.halfSize.x() + margin && std::abs(local.y()) <= part.halfSize.y() + margin)
            return std::make_pair(i, local);
    }
    return std::nullopt;
}

}  // namespace jl
