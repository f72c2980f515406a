// Pacing a run for a class: run until the next event, and loop a time range.
#pragma once

#include "ui/play/sim_status.h"

#include <QObject>

#include <memory>

namespace jl::ui {

class SimController;

class Pacing : public QObject {
    Q_OBJECT
public:
    explicit Pacing(SimController* sim, QObject* parent = nullptr);

    // Shows the ladder at the instant of the next event after the moment on
    // screen (the state just after it: a lock locked, a flip flipped),
    // simulating on first if needed (in short stretches, so the window stays
    // live) until one happens or `limit` seconds pass.
    void runToNextEvent(double limit = 10.0);
    bool seekingEvent() const { return searching_; }

    // While playing, the cursor returns to `from` when it passes `to`.
    void setLoop(double from, double to);
    void clearLoop();
    bool looping() const { return loop_; }
    double loopFrom() const { return from_; }
    double loopTo() const { return to_; }

signals:
    // Said in words when there is something to say ("no event in the next 10 s").
    void message(const QString& text);
    void loopChanged(bool on);

private:
    void onStatus(std::shared_ptr<const jl::ui::SimStatus> s);
    void searchFurther(const SimStatus& s);

    SimController* sim_;
    bool searching_ = false;
    double searchFrom_ = 0, searchUntil_ = 0, requested_ = 0;
    bool loop_ = false;
    double from_ = 0, to_ = 0;
};

}  // namespace jl::ui
