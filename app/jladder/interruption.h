// Ctrl-C (SIGINT) and kill's default signal (SIGTERM) end a headless run
// between two steps instead of at once, so that it can keep what it
// computed; a second such signal ends the process at once.
#pragma once

namespace jl::cli {

void catchInterruptions();
// The signal caught since, or 0.
int interruption();
// Ends the process by the signal caught, as if it had not been caught, so
// that a calling shell sees it (a loop over scenes stops at Ctrl-C).
[[noreturn]] void endByInterruption();

}  // namespace jl::cli
