#!/usr/bin/env bash
# Install what is missing, build, and run every test with CTest under xvfb-run.
#
# Before the main run, the sanitizers run in a short form (JL_SANITIZERS=0
# skips them): AddressSanitizer + UndefinedBehaviorSanitizer over the engine,
# the ladder, the scene loader and its mutation fuzzer; ThreadSanitizer over
# the hand-off between the UI thread and the simulation thread. Slow suites
# (label "hard") run their short forms; JL_SOAK=1 runs the long ones.
set -euo pipefail
cd "$(dirname "$0")"
source tools/setup.sh
jl_install "${JL_TEST_PACKAGES[@]}"
# Warnings are errors in our own code here (not for a user's ./run.sh).
jl_build build -DJL_WERROR=ON

xvfb() { xvfb-run -a -s "-screen 0 1600x1000x24" "$@"; }

if [ "${JL_SANITIZERS:-1}" = 1 ]; then
  echo "== AddressSanitizer + UndefinedBehaviorSanitizer (engine, ladder, loader, fuzz)"
  jl_configure build-asan -DJL_SANITIZE_ADDRESS=ON -DJL_BUILD_UI=OFF -DJL_WERROR=ON
  jl_compile build-asan
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure --timeout 900 -L "engine|ladder|io|fuzz"

  echo "== ThreadSanitizer (the worker hand-off)"
  jl_configure build-tsan -DJL_SANITIZE_THREAD=ON -DJL_WERROR=ON
  jl_compile build-tsan test_worker_handoff
  TSAN_OPTIONS="halt_on_error=1 suppressions=$PWD/tests/tsan/qt.supp" \
    xvfb ctest --test-dir build-tsan --output-on-failure --timeout 900 -R '^test_worker_handoff$'
fi

# Wall-clock assertions (label timing: no click waits over 100 ms while a
# long ladder plays) measure this machine as much as the program: run on
# their own, nothing else of ours running, and again if a moment of load
# from outside made one miss.
echo "== Timing (wall clock, up to three tries)"
xvfb ctest --test-dir build --output-on-failure --timeout 900 -L timing --repeat until-pass:3

echo "== Every other test"
xvfb ctest --test-dir build --output-on-failure --timeout 900 -LE timing
