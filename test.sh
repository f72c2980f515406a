#!/usr/bin/env bash
# Install what is missing, build, and run every test with CTest under xvfb-run.
# Slow suites (label "soak") run in a short form unless JL_SOAK=1.
set -euo pipefail
cd "$(dirname "$0")"
source tools/setup.sh
jl_install
jl_build build
exec xvfb-run -a -s "-screen 0 1600x1000x24" \
  ctest --test-dir build --output-on-failure --timeout 900
