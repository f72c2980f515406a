// What the 3-D view costs to draw a long ladder held still: the classic
// cascade with N blocks, paused at a fixed instant, drawn a fixed number of
// times in a window of the given size, each frame made to happen by turning
// the camera a little (as a drag off the blocks does) and waited for with a
// capture (so every frame counted was drawn, its read-back included). With
// --reshow the frame is also shown again before each one, as seeking or
// playing does: the view then rebuilds its instance and ribbon buffers.
// Prints, per frame drawn, each thread's CPU time (from /proc/self/task:
// llvmpipe's threads, Qt3D's, the UI thread), the wall time, and the UI
// thread's time in showFrame. Runs only where the 3-D view draws: an X
// server (Xvfb) with QT3D_RENDERER=opengl; see tools/view_draw_cost.sh.
#include "jl/scene/scene_io.h"
#include "jl/sim/simulation.h"
#include "tests/ui/thread_seconds.h"
#include "ui/view3d/ladder_view.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QGuiApplication>
#include <QImage>
#include <QTimer>
#include <Qt3DRender/QRenderCapture>

#include <cstdio>
#include <memory>

namespace {

// The next frame drawn, waited for; a null image if none comes in 20 s.
QImage nextFrame(jl::ui::LadderView& view) {
    std::unique_ptr<Qt3DRender::QRenderCaptureReply> reply(view.capture()->requestCapture());
    QEventLoop wait;
    QTimer::singleShot(20000, &wait, &QEventLoop::quit);
    QObject::connect(reply.get(), &Qt3DRender::QRenderCaptureReply::completed, &wait, &QEventLoop::quit);
    if (!reply->isComplete()) wait.exec();
    return reply->isComplete() ? reply->image() : QImage();
}

// Turns the camera and waits for the frame drawn after it.
bool drawOnce(jl::ui::LadderView& view, float yaw) {
    view.orbit(yaw, 0);
    return !nextFrame(view).isNull();
}

}  // namespace

int main(int argc, char** argv) {
    QGuiApplication app(argc, argv);
    QCommandLineParser args;
    args.addHelpOption();
    args.addOptions({{"blocks", "Blocks in the ladder.", "n", "10000"},
                     {"at", "The instant shown (s).", "t", "0.6"},
                     {"frames", "Frames measured.", "n", "40"},
                     {"size", "Window size.", "WxH", "1440x900"},
                     {"close", "Look at the top blocks (ribbons drawn) instead of the whole ladder."},
                     {"hide-ribbons", "The scene's ribbons hidden."},
                     {"frame-ribbons", "The simulation puts the ribbons in the frame (as the worker did once)."},
                     {"reshow", "Show the frame again before each frame drawn (seeking, playing)."},
                     {"shot", "Save the last frame drawn to this file.", "png"}});
    args.process(app);
    const int frames = args.value("frames").toInt();
    const QStringList size = args.value("size").split('x');

    auto load = jl::loadScene(JL_SOURCE_DIR "/examples/classic.yaml");
    if (!load.scene) return 1;
    jl::Scene scene = *load.scene;
    scene.ladder->blocks = args.value("blocks").toInt();
    scene.ladder->ribbons.visible = !args.isSet("hide-ribbons");
    if (args.isSet("close")) scene.view.target = {0, -0.3}, scene.view.distance = 0.9;
    auto built = jl::Simulation::build(scene);
    if (!built.simulation) return 1;
    jl::Simulation& sim = *built.simulation;
    sim.setRibbonsInFrames(args.isSet("frame-ribbons"));
    sim.advanceTo(args.value("at").toDouble());
    const jl::Frame frame = sim.frame();

    jl::ui::LadderView view;
    view.resize(size.value(0).toInt(), size.value(1).toInt());
    view.show();
    view.setScene(scene, true);
    view.showFrame(frame);
    for (int i = 0; i < 10; ++i)  // shaders, buffers and the window's first frames
        if (!drawOnce(view, i % 2 ? 1.0f : -1.0f)) return 2;

    qint64 showNs = 0;
    QElapsedTimer wall, show;
    const auto before = jl::test::threadSeconds();
    wall.start();
    for (int i = 0; i < frames; ++i) {
        if (args.isSet("reshow")) {
            show.start();
            view.showFrame(frame);
            showNs += show.nsecsElapsed();
        }
        if (!drawOnce(view, i % 2 ? 1.0f : -1.0f)) return 2;
    }
    const double wallMs = double(wall.nsecsElapsed()) / 1e6 / frames;
    const auto after = jl::test::threadSeconds();
    std::printf("%d blocks at t = %s s, %s, ribbons %s, %d frames (%s): wall %.1f ms/frame, showFrame %.2f ms\n",
                scene.ladder->blocks, qPrintable(args.value("at")), args.isSet("close") ? "close" : "whole",
                args.isSet("hide-ribbons") ? "hidden" : "shown", frames, args.isSet("reshow") ? "reshow" : "orbit",
                wallMs, double(showNs) / 1e6 / frames);
    for (const auto& [name, seconds] : after) {
        const double used = seconds - (before.count(name) ? before.at(name) : 0.0);
        if (used > 0) std::printf("  cpu %-16s %7.2f ms/frame\n", name.c_str(), used * 1000 / frames);
    }
    if (args.isSet("shot") && !nextFrame(view).save(args.value("shot"))) return 3;
    return 0;
}
