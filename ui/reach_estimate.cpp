#include "ui/reach_estimate.h"

#include "ui/design_map_cache.h"

#include <QTimer>
#include <QtConcurrent>

namespace jl::ui {

ReachEstimate::ReachEstimate(QWidget* parent) : QLabel(parent) {
    setObjectName("reachEstimate");
    setWordWrap(true);
    setToolTip(
        tr("How far the first ripple travels down this design when the script turns the top block, "
           "simulated in the background after every change (docs/model.md section 15)."));
    pool_.setMaxThreadCount(1);
    settle_ = new QTimer(this);
    settle_->setSingleShot(true);
    settle_->setInterval(250);
    connect(settle_, &QTimer::timeout, this, &ReachEstimate::start);
    connect(&watcher_, &QFutureWatcher<jl::RippleReach>::finished, this, [this] {
        const jl::RippleReach r = watcher_.result();
        ReachCache::shared().keep(runKey_, r);
        if (runKey_ != key_ || r.cancelled) return;  // stale: a newer design is on its way
        computing_ = false;
        show(r);
    });
}

ReachEstimate::~ReachEstimate() {
    // The pool waits for its one run, which sees the flag within one step.
    if (stop_) stop_->store(true);
    watcher_.disconnect(this);
}

void ReachEstimate::estimate(const jl::Scene& scene) {
    if (!scene.ladder) {
        key_.clear();
        settle_->stop();
        if (stop_) stop_->store(true);
        computing_ = false;
        setText({});
        return;
    }
    const QByteArray key = ReachCache::designKey(scene);
    if (key == key_) return;
    key_ = key;
    design_ = scene;
    if (stop_) stop_->store(true);  // the older design's run is of no use now
    if (const auto r = ReachCache::shared().find(key)) {
        settle_->stop();
        computing_ = false;
        show(*r);
        return;
    }
    computing_ = true;
    setText(tr("First ripple: computing..."));
    settle_->start();
}

void ReachEstimate::start() {
    runKey_ = key_;
    stop_ = std::make_shared<std::atomic<bool>>(false);
    watcher_.setFuture(QtConcurrent::run(
        &pool_, [design = design_, stop = stop_] { return jl::firstRippleReach(design, stop.get()); }));
}

void ReachEstimate::show(const jl::RippleReach& r) {
    QString text = r.reached >= r.hinges && r.hinges > 0
                       ? tr("The first ripple reaches the bottom: hinge %1 of %2").arg(r.reached).arg(r.hinges)
                       : tr("The first ripple reaches hinge %1 of %2").arg(r.reached).arg(r.hinges);
    if (r.reached >= 2) text += tr(", one flip every %1 s").arg(r.meanTimeBetweenFlips, 0, 'f', 3);
    if (!r.failure.empty()) text += tr("; the run failed: %1").arg(QString::fromStdString(r.failure));
    setText(text);
    emit estimated();
}

}  // namespace jl::ui
