#!/usr/bin/env bash
# Install what is missing, build (Release, Ninja) and start the desktop program.
# Usage: ./run.sh [scene.yaml]
set -euo pipefail
cd "$(dirname "$0")"
source tools/setup.sh
jl_install
jl_build build
exec build/bin/jacobsladder "${1:-examples/classic.yaml}"
