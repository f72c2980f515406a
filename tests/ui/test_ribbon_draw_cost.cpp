// labels: ui;timing
// Close to the top of a 10,000-block ladder, where the 3-D view draws the
// ribbons, each frame shown (playing, seeking) costs the UI thread about what
// it costs with the ribbons hidden: the view makes only the ribbons of the
// blocks near it, as instances of their paths. Made as quads for every hinge,
// the ribbons took 11 to 46 ms of each showFrame here (the machine loaded or
// not), against 0.4 ms without them.
// Wall-clock on the UI thread, so the label `timing` lets a loaded machine
// leave it out (ctest -LE timing).
#include "jl/scene/scene_io.h"
#include "jl/sim/simulation.h"
#include "ui/view3d/ladder_view.h"
#include "ui/view3d/view_capture.h"

#include <QElapsedTimer>
#include <QtTest>

#include <algorithm>
#include <vector>

using namespace jl::ui;

namespace {

constexpr int kBlocks = 10000;
constexpr int kFrames = 30;

// The classic cascade with 10,000 blocks, looked at from 0.9 m at its top,
// its outer pair pure blue.
jl::Scene closeToTheTop(bool ribbons) {
    auto load = jl::loadScene(JL_SOURCE_DIR "/examples/classic.yaml");
    if (!load.scene) qFatal("examples/classic.yaml does not load");
    jl::Scene s = *load.scene;
    s.ladder->blocks = kBlocks;
    s.ladder->ribbons.visible = ribbons;
    s.ladder->ribbons.color = {0, 0, 255};
    s.view.target = {0, -0.3};
    s.view.distance = 0.9;
    return s;
}

int bluePixels(const QImage& image) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb c = image.pixel(x, y);
            n += qBlue(c) > qRed(c) + 60 && qBlue(c) > qGreen(c) + 40;
        }
    return n;
}

struct Shown {
    double medianMs = 0;  // of showFrame, on the UI thread
    int blue = 0;         // pixels of the outer pair in the last frame drawn
};

// Shows the same frame kFrames times in a 1440 x 900 view, as the window
// does with each frame it is given.
Shown showRepeatedly(const jl::Scene& scene, const jl::Frame& frame) {
    LadderView view;
    view.resize(1440, 900);
    view.show();
    if (!QTest::qWaitForWindowExposed(&view)) qFatal("the view is not on screen");
    view.setScene(scene, true);
    view.showFrame(frame);
    captureView(&view);  // shaders and buffers made once
    std::vector<double> ms;
    QElapsedTimer clock;
    for (int i = 0; i < kFrames; ++i) {
        clock.start();
        view.showFrame(frame);
        ms.push_back(double(clock.nsecsElapsed()) / 1e6);
        QCoreApplication::processEvents();
    }
    std::nth_element(ms.begin(), ms.begin() + kFrames / 2, ms.end());
    return {ms[kFrames / 2], bluePixels(captureView(&view))};
}

}  // namespace

class RibbonDrawCost : public QObject {
    Q_OBJECT
private slots:
    void aFrameShownCloseUpCostsLittleMoreWithRibbons() {
        auto built = jl::Simulation::build(closeToTheTop(true));
        QVERIFY(built.simulation);
        built.simulation->setRibbonsInFrames(false);  // as the window's worker records them
        built.simulation->advanceTo(0.6);
        const jl::Frame frame = built.simulation->frame();

        const Shown with = showRepeatedly(closeToTheTop(true), frame);
        const Shown without = showRepeatedly(closeToTheTop(false), frame);
        qInfo("showFrame, median of %d: %.2f ms with the ribbons (%d blue pixels), %.2f ms without (%d)", kFrames,
              with.medianMs, with.blue, without.medianMs, without.blue);
        QVERIFY2(with.blue > 1000, "the ribbons are drawn");
        QCOMPARE(without.blue, 0);
        // 1.2 times, as the drawing's target, and a millisecond for a busy machine's noise.
        QVERIFY2(with.medianMs <= 1.2 * without.medianMs + 1.0,
                 qPrintable(QString("%1 ms against %2 ms").arg(with.medianMs).arg(without.medianMs)));
    }
};

QTEST_MAIN(RibbonDrawCost)
#include "test_ribbon_draw_cost.moc"
