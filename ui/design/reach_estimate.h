// The ladder editor's live estimate: how far the first ripple of the design
// on screen travels ("the ripple reaches hinge 9 of 11"), simulated in the
// background whenever the design changes. The newest design wins: an older
// run is stopped and its result dropped; the UI never waits on a run.
#pragma once

#include "jl/design/design_axis.h"
#include "jl/design/ripple_reach.h"

#include <QByteArray>
#include <QFutureWatcher>
#include <QLabel>
#include <QThreadPool>

#include <atomic>
#include <memory>

class QTimer;

namespace jl::ui {

class ReachEstimate : public QLabel {
    Q_OBJECT
public:
    explicit ReachEstimate(QWidget* parent = nullptr);
    ~ReachEstimate() override;

    // The design to estimate; the same design again changes nothing.
    void estimate(const jl::Scene& scene);
    bool computing() const { return computing_; }
    // The words drawn: the whole text when it fits the reserved lines, else
    // as many of its words as fit, then "..." (the tooltip has them all).
    QString shownText() const;

signals:
    void estimated();  // the label shows the newest design's result

protected:
    void paintEvent(QPaintEvent*) override;
    void changeEvent(QEvent* e) override;

private:
    void reserveLines();
    void say(const QString& text);
    void start();
    void show(const jl::RippleReach& r);

    jl::Scene design_;
    double longest_ = 0;       // s of simulated time the run may take (the design's whole run, or less)
    QByteArray key_;           // of the design asked for last (and of its run: see estimate)
    QByteArray runKey_;        // of the design being run
    QByteArray runDesignKey_;  // of that design's whole run, which a first look that settles is
    bool computing_ = false;
    QTimer* settle_;  // a burst of edits (typing 1000) starts one run
    std::shared_ptr<std::atomic<bool>> stop_;
    QFutureWatcher<jl::RippleReach> watcher_;
    QThreadPool pool_;  // one thread, apart from the design map's
};

}  // namespace jl::ui
