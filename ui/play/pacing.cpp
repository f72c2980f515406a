#include "ui/play/pacing.h"

#include "ui/play/sim_controller.h"

#include <algorithm>

namespace jl::ui {

namespace {
// Simulated seconds asked for at a time while looking for the next event: a
// long ladder takes a while per second, and the user may want to stop.
constexpr double kStretch = 0.25;

const jl::Event* firstEventAfter(const SimStatus& s, double t) {
    if (!s.events) return nullptr;
    const auto it = std::upper_bound(s.events->begin(), s.events->end(), t + 1e-9,
                                     [](double time, const jl::Event& e) { return time < e.time; });
    return it == s.events->end() ? nullptr : &*it;
}
}  // namespace

Pacing::Pacing(SimController* sim, QObject* parent) : QObject(parent), sim_(sim) {
    connect(sim_, &SimController::statusChanged, this, &Pacing::onStatus);
}

void Pacing::runToNextEvent(double limit) {
    const auto s = sim_->status();
    if (!s || !s->frame) return;
    sim_->pause();
    const double now = s->frame->time;
    if (const jl::Event* e = firstEventAfter(*s, now)) return sim_->showInstant(e->time);
    searching_ = true;
    searchFrom_ = now;
    searchUntil_ = std::max(now, s->headTime) + limit;
    searchFurther(*s);
}

void Pacing::searchFurther(const SimStatus& s) {
    requested_ = std::min(searchUntil_, std::max(s.headTime, s.frame ? s.frame->time : 0) + kStretch);
    sim_->seek(requested_);
}

void Pacing::onStatus(std::shared_ptr<const SimStatus> s) {
    if (!s->frame) return;
    if (searching_) {
        if (!s->failure.empty()) {
            searching_ = false;
            return;
        }
        if (const jl::Event* e = firstEventAfter(*s, searchFrom_)) {
            searching_ = false;
            return sim_->showInstant(e->time);
        }
        // Wait until the stretch asked for is on screen, then ask for the next.
        if (s->frame->time + s->interval < requested_ - 1e-9) return;
        if (requested_ >= searchUntil_ - 1e-9) {
            searching_ = false;
            emit message(tr("No event in the next %1 s.").arg(searchUntil_ - searchFrom_, 0, 'g', 3));
            return;
        }
        searchFurther(*s);
        return;
    }
    if (loop_ && s->playing && (s->frame->time > to_ || s->frame->time < from_ - s->interval)) sim_->seek(from_);
}

void Pacing::setLoop(double from, double to) {
    if (to <= from) return clearLoop();
    loop_ = true;
    from_ = from;
    to_ = to;
    emit loopChanged(true);
}

void Pacing::clearLoop() {
    if (!loop_) return;
    loop_ = false;
    emit loopChanged(false);
}

}  // namespace jl::ui
