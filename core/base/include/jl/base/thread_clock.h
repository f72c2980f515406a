// CPU time of the calling thread: the benchmark's clock, and the engine's
// for the phases it reports (as MuJoCo's timers and Box2D's profile do). On
// a shared machine it is what one core would take; wall time also counts
// other people's work.
#pragma once

#include <ctime>

namespace jl {

inline double threadSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Adds to `*total` the thread's CPU time from its making to its end: one
// phase timed on every way out of it. Null: nothing is timed (reading the
// clock is a system call, some 0.5 us here, which on a short ladder is a
// few per cent of an event).
class ThreadSecondsInto {
public:
    explicit ThreadSecondsInto(double* total) : total_(total), start_(total ? threadSeconds() : 0) {}
    ~ThreadSecondsInto() {
        if (total_) *total_ += threadSeconds() - start_;
    }
    ThreadSecondsInto(const ThreadSecondsInto&) = delete;
    ThreadSecondsInto& operator=(const ThreadSecondsInto&) = delete;

private:
    double* total_;
    double start_;
};

}  // namespace jl
