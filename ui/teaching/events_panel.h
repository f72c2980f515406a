// The Events dock: the event log in words; choosing an event shows its instant.
#pragma once

#include "jl/sim/frame.h"

#include <QWidget>

#include <map>
#include <memory>
#include <optional>
#include <vector>

class QListWidget;
class QListWidgetItem;

namespace jl::ui {

QString eventInWords(const jl::Event& e);
// The same without its time: "blocks 0 and 1 lock end to end".
QString whatHappened(const jl::Event& e);
// Events of one instant: "0.512 s: block 1 folds ...; block 2 flips ...".
QString eventsInWords(const std::vector<jl::Event>& events);
// The hinges (1..N-1) of the events at the frame's own instant, the one an
// event's entry or mark shows: the views point at them.
std::vector<int> hingesAtInstant(const jl::Frame& frame);

class EventsPanel : public QWidget {
    Q_OBJECT
public:
    explicit EventsPanel(QWidget* parent = nullptr);
    void setEvents(std::shared_ptr<const std::vector<jl::Event>> events);
    // The time on screen: the latest event at or before it is selected, so
    // the log follows a scrub and says what last happened.
    void setTime(double t);
    // The time of the selected row, if any.
    std::optional<double> selectedTime() const;

signals:
    void instantRequested(double time);

private:
    // A pair resting against each other with almost no force locks and
    // unlocks every few milliseconds (grazing contact): from two cycles on,
    // the run is one row, so the log still reads as a story.
    struct Run {
        size_t first = 0, last = 0;          // event indices
        int count = 0;                       // events in the run
        std::vector<QListWidgetItem*> rows;  // one row each until merged, then the run's row
    };
    void append(size_t index);
    QListWidgetItem* addRow(const QString& text, double time);

    void follow();

    QListWidget* list_;
    double time_ = 0;
    std::shared_ptr<const std::vector<jl::Event>> events_;
    std::map<int, Run> runs_;  // by hinge: its latest run of locks and unlocks
};

}  // namespace jl::ui
