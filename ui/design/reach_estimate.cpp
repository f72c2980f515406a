#include "ui/design/reach_estimate.h"

#include "ui/design/design_map_cache.h"

#include <QPainter>
#include <QThread>
#include <QTimer>
#include <QtConcurrent>

namespace jl::ui {

namespace {
// The estimate runs beside the simulation, on a machine that may have two
// cores: at most this many block-seconds of simulated time. A design of 200
// blocks runs whole (40 s); one of 1,000 blocks its first 10 s of 200 (a
// whole run is a hundred CPU seconds); 10,000 blocks their first second
// (a whole run, 2,000 s simulated, would take hours).
constexpr double kBlockSeconds = 10000;
// The estimate's height, in lines, whatever it says: a label that grew and
// shrank with its text moved every field below it (and the click meant for
// one landed in another).
constexpr int kLines = 3;

double scriptEnd(const jl::Scene& scene) {
    double end = 0;
    for (const jl::ScriptAction& a : scene.script) end = std::max(end, a.at + std::max(0.0, a.duration));
    return end;
}

QString explanation() {
    return QObject::tr(
        "How far the first ripple travels down this design when the script turns the top block, "
        "simulated in the background after every change (docs/model.md section 15).");
}
}  // namespace

ReachEstimate::ReachEstimate(QWidget* parent) : QLabel(parent) {
    setObjectName("reachEstimate");
    setWordWrap(true);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    reserveLines();
    setToolTip(explanation());
    pool_.setMaxThreadCount(1);
    settle_ = new QTimer(this);
    settle_->setSingleShot(true);
    settle_->setInterval(250);
    connect(settle_, &QTimer::timeout, this, &ReachEstimate::start);
    connect(&watcher_, &QFutureWatcher<jl::RippleReach>::finished, this, [this] {
        const jl::RippleReach r = watcher_.result();
        ReachCache::shared().keep(runKey_, r);
        // A first look that stopped because its reach was settled is the
        // design's answer, the one the design map computes for it too.
        if (r.whole && !r.cancelled && runKey_ != runDesignKey_) ReachCache::shared().keep(runDesignKey_, r);
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
        say({});
        return;
    }
    const QByteArray whole = ReachCache::designKey(scene);
    // A first look at a long design is a different run from its whole run:
    // the cache keeps them apart (the design map must never show a first look).
    const int blocks = scene.ladder->blocks;
    const double longest = std::min(jl::rippleRunTime(scene), kBlockSeconds / std::max(1, blocks));
    const QByteArray key = longest < jl::rippleRunTime(scene) ? whole + "@" + QByteArray::number(longest) : whole;
    if (key == key_) return;
    key_ = key;
    design_ = scene;
    longest_ = longest;
    if (stop_) stop_->store(true);  // the older design's run is of no use now
    for (const QByteArray& k : {whole, key})
        if (const auto r = ReachCache::shared().find(k)) {
            settle_->stop();
            computing_ = false;
            show(*r);
            return;
        }
    // Too long to see even the turn and what follows it within the budget.
    if (longest < scriptEnd(scene) + 0.5) {
        settle_->stop();
        computing_ = false;
        say(tr("First ripple: not estimated for a ladder of %1 blocks, which would take long to run; the design map "
               "runs any design whole.")
                .arg(blocks));
        emit estimated();
        return;
    }
    computing_ = true;
    say(tr("First ripple: computing..."));
    settle_->start();
}

void ReachEstimate::start() {
    runKey_ = key_;
    runDesignKey_ = ReachCache::designKey(design_);
    stop_ = std::make_shared<std::atomic<bool>>(false);
    watcher_.setFuture(QtConcurrent::run(&pool_, [design = design_, stop = stop_, longest = longest_] {
        // Only on a core nobody else wants: the simulation the user
        // watches and the window come first. At the ordinary priority a
        // 1,000-block estimate took 1.6 to 2.4 CPU s of the first 6 s of
        // playing its design on two cores busy with other work too; the
        // simulation thread got 1.05 to 1.25 CPU s instead of 1.7, and the
        // run played at 0.43x to 0.53x instead of 0.55x to 0.61x
        // (docs/desktop-performance.md).
        QThread::currentThread()->setPriority(QThread::IdlePriority);
        return jl::firstRippleReach(design, stop.get(), longest);
    }));
}

void ReachEstimate::show(const jl::RippleReach& r) {
    QString text =
        !r.whole ? tr("In the first %1 s (a whole run of this design is %2 s), the first ripple reaches hinge %3 of %4")
                       .arg(r.until, 0, 'g', 3)
                       .arg(jl::rippleRunTime(design_), 0, 'f', 0)
                       .arg(r.reached)
                       .arg(r.hinges)
        : r.reached >= r.hinges && r.hinges > 0
            ? tr("The first ripple reaches the bottom: hinge %1 of %2").arg(r.reached).arg(r.hinges)
            : tr("The first ripple reaches hinge %1 of %2").arg(r.reached).arg(r.hinges);
    if (r.reached >= 2) text += tr(", one flip every %1 s").arg(r.meanTimeBetweenFlips, 0, 'f', 3);
    if (!r.failure.empty()) text += tr("; the run failed: %1").arg(QString::fromStdString(r.failure));
    say(text);
    emit estimated();
}

void ReachEstimate::say(const QString& text) {
    setText(text);
    setToolTip(text.isEmpty() ? explanation() : text + "\n\n" + explanation());
}

void ReachEstimate::reserveLines() {
    const QMargins m = contentsMargins();
    setFixedHeight(kLines * fontMetrics().lineSpacing() + m.top() + m.bottom());
}

void ReachEstimate::changeEvent(QEvent* e) {
    QLabel::changeEvent(e);
    if (e->type() == QEvent::FontChange) reserveLines();
}

QString ReachEstimate::shownText() const {
    const QRect box = contentsRect();
    const auto fits = [&](const QString& t) {
        return fontMetrics().boundingRect(QRect(0, 0, box.width(), 1 << 20), Qt::TextWordWrap, t).height() <=
               box.height();
    };
    if (fits(text())) return text();
    QStringList words = text().split(' ');
    while (words.size() > 1) {
        words.removeLast();
        const QString shorter = words.join(' ') + QChar(0x2026);
        if (fits(shorter)) return shorter;
    }
    return QString(QChar(0x2026));
}

void ReachEstimate::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(contentsRect(), Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap, shownText());
}

}  // namespace jl::ui
