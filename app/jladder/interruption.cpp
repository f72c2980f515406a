#include "app/jladder/interruption.h"

#include <csignal>
#include <cstdlib>

namespace jl::cli {

namespace {

volatile std::sig_atomic_t caught = 0;

void onSignal(int signal) { caught = signal; }

}  // namespace

void catchInterruptions() {
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // the second signal takes the default course
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int interruption() { return caught; }

void endByInterruption() {
    std::signal(caught, SIG_DFL);
    std::raise(caught);
    std::exit(128 + caught);  // not reached unless the signal is blocked
}

}  // namespace jl::cli
