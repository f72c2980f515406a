#!/usr/bin/env bash
# Shared set-up for run.sh and test.sh: install what is missing, configure and
# build. Sourced, so it sets BUILD_DIR for the caller.
set -euo pipefail

JL_PACKAGES=(build-essential cmake ninja-build qt6-base-dev qt6-3d-dev
  libqt6opengl6-dev qt6-charts-dev qt6-svg-dev libeigen3-dev libyaml-cpp-dev
  nlohmann-json3-dev
  libgl1-mesa-dev xvfb xauth)
# What only ./test.sh needs: a window manager and xwininfo for the window's
# fit on the screen, clang-format for the house style, GNU parallel for
# the design map computed in shares.
JL_TEST_PACKAGES=(openbox x11-utils clang-format parallel)

# jl_missing_packages [more packages...]: those of JL_PACKAGES and the more not installed.
jl_missing_packages() {
  local missing=()
  for p in "${JL_PACKAGES[@]}" "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  echo "${missing[@]:-}"
}

# jl_install [more packages...]
jl_install() {
  local missing
  missing=$(jl_missing_packages "$@")
  [ -z "$missing" ] && return 0
  if [ "$(id -u)" -eq 0 ]; then
    echo "Installing: $missing"
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing
  else
    echo "These packages are missing. Install them, then run this again:" >&2
    echo "  sudo apt-get install --no-install-recommends $missing" >&2
    exit 1
  fi
}

# jl_configure DIR [cmake options...]: configure once (Release, Ninja); an
# existing build takes the options given again into its cache.
jl_configure() {
  local dir=$1; shift
  if [ ! -f "$dir/build.ninja" ]; then
    cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
  elif [ $# -gt 0 ]; then
    cmake -B "$dir" "$@" >/dev/null
  fi
}

# jl_compile DIR [targets...]: build incrementally, on every core.
jl_compile() {
  local dir=$1; shift
  cmake --build "$dir" -j "${JL_JOBS:-$(nproc)}" ${1:+--target "$@"}
}

# jl_build DIR [cmake options...]: both, every target.
jl_build() {
  jl_configure "$@"
  jl_compile "$1"
}
