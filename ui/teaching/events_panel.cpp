#include "ui/teaching/events_panel.h"

#include <QListWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace jl::ui {

namespace {

constexpr double kRunGap = 0.01;  // s: a lock and an unlock of one hinge this close belong to one run
constexpr int kRunRow = 4;        // events: two lock-unlock cycles and more make one row

bool lockOrUnlock(const jl::Event& e) {
    return e.hinge > 0 && (e.kind == jl::EventKind::Lock || e.kind == jl::EventKind::Unlock);
}

QString runInWords(const jl::Event& first, const jl::Event& last, int count) {
    return QObject::tr(
               "%1–%2 s: blocks %3 and %4 lock and unlock again and again (%5 events): they rest against each "
               "other with almost no force")
        .arg(first.time, 0, 'f', 3)
        .arg(last.time, 0, 'f', 3)
        .arg(first.hinge - 1)
        .arg(first.hinge)
        .arg(count);
}

// A lock and an unlock of one hinge at one instant: the pair closes and the
// impact's own impulse parts it again (the knocks down a long ladder's free
// end), one row rather than two that read as if nothing happened.
QString knockInWords(const jl::Event& e) {
    return QObject::tr("%1 s: blocks %2 and %3 knock end to end").arg(e.time, 0, 'f', 3).arg(e.hinge - 1).arg(e.hinge);
}

}  // namespace

QString whatHappened(const jl::Event& e) {
    QString what = QString::fromStdString(e.text);
    if (what.isEmpty()) what = QObject::tr("hinge %1: %2").arg(e.hinge).arg(QString::fromUtf8(jl::toString(e.kind)));
    return what;
}

QString eventInWords(const jl::Event& e) { return QString("%1 s: %2").arg(e.time, 0, 'f', 3).arg(whatHappened(e)); }

QString eventsInWords(const std::vector<jl::Event>& events) {
    if (events.empty()) return {};
    QStringList what;
    for (const jl::Event& e : events) what << whatHappened(e);
    return QString("%1 s: %2").arg(events.front().time, 0, 'f', 3).arg(what.join("; "));
}

std::vector<int> hingesAtInstant(const jl::Frame& frame) {
    std::vector<int> hinges;
    for (const jl::Event& e : frame.events)
        if (e.time == frame.time && e.hinge >= 1 && e.hinge <= int(frame.hinges.size()) &&
            std::find(hinges.begin(), hinges.end(), e.hinge) == hinges.end())
            hinges.push_back(e.hinge);
    return hinges;
}

EventsPanel::EventsPanel(QWidget* parent) : QWidget(parent) {
    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    list_ = new QListWidget(this);
    list_->setObjectName("events");
    list_->setToolTip(tr("What happened at each hinge, in order; click one to see the ladder at that instant."));
    list_->setUniformItemSizes(true);
    box->addWidget(list_);
    connect(list_, &QListWidget::itemClicked, this,
            [this](QListWidgetItem* item) { emit instantRequested(item->data(Qt::UserRole).toDouble()); });
}

QListWidgetItem* EventsPanel::addRow(const QString& text, double time) {
    auto* item = new QListWidgetItem(text, list_);
    item->setData(Qt::UserRole, time);
    return item;
}

// One more event: a row of its own, or part of its hinge's run of locks and
// unlocks (whose row seeks to the run's start).
void EventsPanel::append(size_t index) {
    const jl::Event& e = (*events_)[index];
    auto it = runs_.find(e.hinge);
    if (lockOrUnlock(e) && it != runs_.end() && e.time - (*events_)[it->second.last].time <= kRunGap) {
        Run& run = it->second;
        const jl::Event& before = (*events_)[run.last];
        const bool knock =
            e.kind == jl::EventKind::Unlock && before.kind == jl::EventKind::Lock && before.time == e.time;
        run.last = index;
        ++run.count;
        if (run.count < kRunRow) {
            if (knock) {  // the lock's row
                run.rows.back()->setText(knockInWords(e));
                run.rows.back()->setToolTip(
                    tr("A lock and an unlock at one instant: the two blocks close end to end "
                       "and the impact parts them again at once."));
            } else
                run.rows.push_back(addRow(eventInWords(e), e.time));
            return;
        }
        if (run.count == kRunRow) {
            for (size_t k = 1; k < run.rows.size(); ++k) delete list_->takeItem(list_->row(run.rows[k]));
            run.rows.resize(1);
            run.rows.front()->setToolTip({});  // it may have been a knock's row
        }
        run.rows.front()->setText(runInWords((*events_)[run.first], e, run.count));
        return;
    }
    QListWidgetItem* row = addRow(eventInWords(e), e.time);
    if (lockOrUnlock(e))
        runs_[e.hinge] = Run{index, index, 1, {row}};
    else if (e.hinge > 0)
        runs_.erase(e.hinge);  // a fold or a flip ends the hinge's run
}

void EventsPanel::setEvents(std::shared_ptr<const std::vector<jl::Event>> events) {
    if (events == events_) return;
    const size_t had = (events_ && events && events->size() >= events_->size()) ? events_->size() : 0;
    // The log only grows while playing: append; anything else rebuilds it.
    if (had == 0) {
        list_->clear();
        runs_.clear();
    }
    events_ = std::move(events);
    if (!events_) return;
    for (size_t i = had; i < events_->size(); ++i) append(i);
    if (had < events_->size()) list_->scrollToBottom();
    follow();
}

void EventsPanel::setTime(double t) {
    if (t == time_) return;
    time_ = t;
    follow();
}

// Rows are in time order (a run's row at its first event): the last row at
// or before the time on screen.
void EventsPanel::follow() {
    int lo = 0, hi = list_->count();
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (list_->item(mid)->data(Qt::UserRole).toDouble() <= time_ + 1e-12)
            lo = mid + 1;
        else
            hi = mid;
    }
    const int row = lo - 1;
    if (row == list_->currentRow()) return;
    if (row < 0) {
        list_->clearSelection();
        list_->setCurrentRow(-1);
        return;
    }
    list_->setCurrentRow(row);
    list_->scrollToItem(list_->item(row));
}

std::optional<double> EventsPanel::selectedTime() const {
    const QListWidgetItem* item = list_->currentItem();
    if (!item || !item->isSelected()) return std::nullopt;
    return item->data(Qt::UserRole).toDouble();
}

}  // namespace jl::ui
