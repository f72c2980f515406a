// Shared by the desktop program's tests: known scenes and waiting on the
// simulation thread's published status without blocking the event loop.
#pragma once

#include "jl/scene/scene_io.h"
#include "ui/play/sim_controller.h"
#include "ui/teaching/time_chart.h"
#include "ui/view3d/ladder_view.h"
#include "ui/view3d/view_capture.h"
#include "ui/window/main_window.h"

#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QGraphicsTextItem>
#include <QScreen>
#include <QStandardPaths>
#include <QTest>
#include <QTimer>
#include <QToolBar>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <memory>
#include <vector>

namespace jl::test {

// A 4-block ladder let go from bent fold angles: it swings, locks and
// unlocks within the first second, quickly enough for any machine.
inline jl::Scene swingingLadder(int blocks = 4) {
    std::string angles = "[0.6";
    for (int j = 2; j < blocks; ++j) angles += ", 0.5";
    angles += "]";
    const std::string text = "format: jacobs-ladder/1\ntitle: swing\nladder:\n  blocks: " + std::to_string(blocks) +
                             "\n  held: [0]\n  initial: {fold_angles: " + angles + "}\nduration: 2\n";
    jl::SceneLoad load = jl::parseScene(text, "swing.yaml");
    if (!load.scene) qFatal("the test scene does not load: %s", load.errors.front().format().c_str());
    return *load.scene;
}

// The program's settings and recovery file go to a test location.
inline void isolateSettings() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("JacobsLadderStudioTests");
    QCoreApplication::setApplicationName("jacobsladder-tests");
}

inline jl::ui::MainWindow::Options quietWindow() { return {false, false}; }

// Clicks the main toolbar's button whose action's text starts with `text`
// ("&Undo", "&Play"), as a user does; false when there is none.
inline bool clickToolButton(jl::ui::MainWindow& w, const QString& text) {
    auto* bar = w.findChild<QToolBar*>("mainToolBar");
    if (!bar) return false;
    for (QAction* a : bar->actions())
        if (a->text().startsWith(text)) {
            QTest::mouseClick(bar->widgetForAction(a), Qt::LeftButton);
            return true;
        }
    return false;
}

// How long this thread has waited for a processor, in ms, or -1 where the
// kernel does not say (/proc/thread-self/schedstat: time run, time waited
// on a run queue, in ns). On a machine busy with other work the UI thread
// waits its turn, and that is no stall of the program's own.
inline double runQueueWaitMs() {
    std::ifstream in("/proc/thread-self/schedstat");
    long long ran = 0, waited = 0;
    if (!(in >> ran >> waited)) return -1;
    return double(waited) / 1e6;
}

// A 5 ms timer on the UI thread: a gap between two of its ticks much
// longer than that is a stall (a click would wait as long), less the time
// the thread spent waiting for a processor (counted apart, in `queued`).
struct EventLoopProbe {
    QElapsedTimer clock;
    QTimer timer;
    qint64 last = 0, worst = 0;
    double lastWait = 0, queued = 0;
    int ticks = 0;
    std::vector<std::pair<qint64, qint64>> gaps;  // (ms since start at its end, its length) of gaps over 25 ms
    void start() {
        timer.setInterval(5);
        QObject::connect(&timer, &QTimer::timeout, [this] {
            const qint64 now = clock.elapsed();
            const double wait = runQueueWaitMs();
            const double waited = lastWait >= 0 && wait >= 0 ? wait - lastWait : 0;
            queued += waited;
            const qint64 gap = now - last - qint64(waited);
            worst = std::max(worst, gap);
            if (gap > 25) gaps.emplace_back(now, gap);
            last = now;
            lastWait = wait;
            ++ticks;
        });
        lastWait = runQueueWaitMs();
        clock.start();
        timer.start();
    }
    void stop() { timer.stop(); }
};

// Waits (running the event loop) until the newest status satisfies `pred`.
template <typename Pred>
bool waitForStatus(jl::ui::SimController* c, Pred pred, int timeoutMs = 20000) {
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < timeoutMs) {
        if (const auto s = c->status(); s && pred(*s)) return true;
        QTest::qWait(5);
    }
    return false;
}

inline std::uint64_t loadsSoFar(jl::ui::SimController* c) { return c->status()->loadSerial; }

// The simulation has built a scene posted after `before` loads and shows its first frame.
inline bool loadedAfter(jl::ui::SimController* c, std::uint64_t before) {
    return waitForStatus(
        c, [before](const jl::ui::SimStatus& s) { return s.loadSerial > before && s.frame && s.failure.empty(); });
}

// Shows the window at a size with room for the 3-D view, on the scene file
// `path` with its first frame simulated.
inline bool showScene(jl::ui::MainWindow& w, const QString& path) {
    w.resize(1400, 900);
    w.show();
    if (!QTest::qWaitForWindowExposed(&w)) return false;
    const auto before = loadsSoFar(w.controller());
    return w.openFile(path) && loadedAfter(w.controller(), before);
}

// What the 3-D view shows (the program's own capture, as its exports take it).
inline QImage captureView(jl::ui::LadderView* view) { return jl::ui::captureView(view); }

// Hue in degrees and saturation of a colour, to recognise the wood under any shading.
inline bool woodColoured(QColor c, QColor wood) {
    const float h = c.hsvHueF() * 360, s = c.hsvSaturationF();
    return std::abs(h - wood.hsvHueF() * 360) < 5 && s > 0.2f && c.valueF() > 0.3f;
}

// Answers the next modal window the program opens that `answer` takes (it
// returns true once it has answered), as a person would: the window is
// modal, so the answer has to come from the event loop.
inline void answerNextModal(const std::function<bool(QWidget*)>& answer) {
    auto* poll = new QTimer;
    auto* waited = new int(0);
    QObject::connect(poll, &QTimer::timeout, [=] {
        QWidget* modal = QApplication::activeModalWidget();
        if (!(modal && answer(modal)) && ++*waited < 250) return;
        poll->stop();
        poll->deleteLater();
        delete waited;
    });
    poll->start(20);
}

// How many of a chart's texts (title, tick labels, legend) Qt cut to "...".
inline int cutLabels(jl::ui::TimeChart* chart) {
    int cut = 0;
    for (QGraphicsItem* item : chart->scene()->items())
        if (auto* text = dynamic_cast<QGraphicsTextItem*>(item))
            if (text->isVisible() &&
                (text->toPlainText().contains("...") || text->toPlainText().contains(QChar(0x2026))))
                ++cut;
    return cut;
}

// How many pixels of `w` as the screen shows it differ (by more than 60
// in the sum of channels) from a fresh drawing of it: a picture kept too
// long, or a repaint missed.
inline int pixelsOffAFreshDrawing(QWidget* w) {
    const QPoint at = w->mapToGlobal(QPoint(0, 0));
    const QImage shown = w->screen()
                             ->grabWindow(0, at.x(), at.y(), w->width(), w->height())
                             .toImage()
                             .convertToFormat(QImage::Format_RGB32);
    const QImage drawn = w->grab().toImage().convertToFormat(QImage::Format_RGB32);
    if (shown.size() != drawn.size()) return w->width() * w->height();
    int differing = 0;
    for (int y = 0; y < drawn.height(); ++y)
        for (int x = 0; x < drawn.width(); ++x) {
            const QColor a = shown.pixelColor(x, y), b = drawn.pixelColor(x, y);
            differing +=
                std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue()) > 60;
        }
    return differing;
}

}  // namespace jl::test
