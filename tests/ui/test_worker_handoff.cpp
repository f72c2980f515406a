// labels: ui;threads
// The hand-off between the UI thread and the simulation thread, built to run
// under ThreadSanitizer: the UI thread posts a storm of commands while reading
// the published status; it never waits on a step, and what it reads is whole.
#include "jl/scene/scene_io.h"
#include "ui/play/sim_controller.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QtTest>

using namespace jl::ui;

class WorkerHandoffTest : public QObject {
    Q_OBJECT
private slots:
    void commandStormWhileReadingStatus() {
        jl::SceneLoad load = jl::loadScene(std::string(JL_SOURCE_DIR) + "/examples/classic.yaml");
        QVERIFY(load.scene);
        SimController controller;
        controller.load(*load.scene);
        controller.setSpeed(4.0);
        controller.play();
        QElapsedTimer clock;
        clock.start();
        qint64 slowestRead = 0;
        std::uint64_t lastSerial = 0;
        int reads = 0;
        for (int i = 0; clock.elapsed() < 3000; ++i) {
            switch (i % 97) {  // a mix of everything the UI can ask for
                case 10:
                    controller.pause();
                    break;
                case 20:
                    controller.stepForward();
                    break;
                case 30:
                    controller.stepBack();
                    break;
                case 40:
                    controller.play();
                    break;
                case 50:
                    controller.seek(0.3);
                    break;
                case 60:
                    controller.beginDrag(jl::Vec2(0.0, -0.1));
                    break;
                case 61:
                    controller.moveDrag(jl::Vec2(0.05, -0.12));
                    break;
                case 70:
                    controller.endDrag();
                    break;
                case 80:
                    controller.setSpeed(0.5 + (i % 7));
                    break;
                default:
                    break;
            }
            QElapsedTimer read;
            read.start();
            const std::shared_ptr<const SimStatus> s = controller.status();
            slowestRead = std::max(slowestRead, read.nsecsElapsed());
            if (s && s->frame) {
                ++reads;
                // A whole snapshot: the frame belongs to the recorded range.
                QVERIFY(s->frameIndex >= 0 && s->frameIndex < std::max(1, s->frameCount));
                QVERIFY(s->frame->time <= s->headTime + 1e-9);
                // Publications arrive in order: an older snapshot never
                // replaces a newer one (the head itself may move back: a
                // drag discards the recorded future).
                QVERIFY2(s->serial >= lastSerial, qPrintable(QString("%1 after %2").arg(s->serial).arg(lastSerial)));
                lastSerial = s->serial;
            }
            QCoreApplication::processEvents();
            QTest::qWait(1);
        }
        QVERIFY(reads > 100);
        QVERIFY(controller.status()->headTime > 0);
        // Reading the status is a pointer copy under a tiny lock, never a step.
        QVERIFY2(slowestRead < 20'000'000, qPrintable(QString("%1 ns").arg(slowestRead)));
    }
};

QTEST_GUILESS_MAIN(WorkerHandoffTest)
#include "test_worker_handoff.moc"
