// The teaching page's pictures of the classic cascade (docs/teaching.md):
// the side view near 0.7 s and the plots of the whole run with the cursor
// there, drawn by the program's own exporter and plots from a run recorded
// as the table exports record it (jl/sim/recording.h). Usage:
// doc_pictures EXAMPLES_DIR OUT_DIR, under an X server; tools/screenshots.sh
// runs it.
#include "jl/scene/scene_io.h"
#include "jl/sim/recording.h"
#include "ui/teaching/exporter.h"
#include "ui/teaching/run_plots.h"

#include <QApplication>
#include <QtTest>

#include <cmath>
#include <cstdio>
#include <memory>

namespace {

// Near 0.7 s, the frame with the most hinges locked or folded: the picture
// shows every colour it can.
const jl::Frame& mostHeldNearSevenTenths(const std::vector<jl::Frame>& frames, double every) {
    size_t at = size_t(std::lround(0.7 / every));
    int most = -1;
    for (size_t i = size_t(0.62 / every); i <= size_t(0.78 / every) && i < frames.size(); ++i) {
        int held = 0;
        for (const jl::HingeFrame& h : frames[i].hinges) held += h.mode != jl::HingeMode::Free;
        if (held > most) most = held, at = i;
    }
    return frames[at];
}

}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    if (argc != 3) {
        std::fprintf(stderr, "usage: doc_pictures EXAMPLES_DIR OUT_DIR\n");
        return 2;
    }
    const QString out = argv[2];
    const jl::SceneLoad load = jl::loadScene(std::string(argv[1]) + "/classic.yaml");
    if (!load.scene) return 1;
    const jl::Scene& scene = *load.scene;
    auto built = jl::Simulation::build(scene);
    if (!built.simulation) return 1;
    jl::WholeRun run;
    run.ribbons = true;  // drawn
    const double every = scene.solver.frameInterval;
    if (!jl::record(*built.simulation, scene.duration, jl::FrameGrid{0, every}, &run).complete()) return 1;

    jl::ui::SideViewOptions look;
    look.cornerNumbers = look.orientation = true;
    const jl::Frame& shown = mostHeldNearSevenTenths(run.frames, every);
    if (!jl::ui::Exporter::sideViewPicture(scene, shown, QSize(900, 1000), look, out + "/side-view.png").ok) return 1;
    std::printf("wrote %s/side-view.png (t = %.3f s)\n", qPrintable(out), shown.time);

    jl::ui::RunPlots plots;
    plots.resize(1000, 900);
    plots.show();
    if (!QTest::qWaitForWindowExposed(&plots)) return 1;
    plots.setDuration(scene.duration);
    plots.setHistory(run.frames);
    plots.setEvents(std::make_shared<const std::vector<jl::Event>>(run.events));
    plots.setCursorTime(0.7);
    QString error;
    if (!plots.savePng(out + "/plots.png", QSize(1000, 900), &error)) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    std::printf("wrote %s/plots.png\n", qPrintable(out));
    return 0;
}
