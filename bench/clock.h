// CPU time of the calling thread: the benchmark's clock. On a shared machine
// it is what one core would take; wall time also counts other people's work.
#pragma once

#include <ctime>

namespace jl::bench {

inline double threadSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace jl::bench
