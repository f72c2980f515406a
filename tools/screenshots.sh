#!/usr/bin/env bash
# The README's and docs' screenshots, made again from the program itself at
# 1440 x 900 under a virtual display: the main window during the classic
# cascade, the design map, presentation mode, the window with the teaching
# docks at 0.75 s, and the teaching page's side view and plots. Needs a build
# (./run.sh or ./test.sh once); writes docs/screenshot-main.png,
# docs/design-map.png, docs/presentation.png, docs/teaching-window.png,
# docs/side-view.png and docs/plots.png. Look at them before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
program=build/bin/jacobsladder
[ -x "$program" ] || { echo "no $program: build first (./test.sh or ./run.sh)" >&2; exit 1; }

shot() {
    local out=$1
    shift
    # A fresh profile each time: the window as a new user first sees it.
    local home
    home=$(mktemp -d)
    HOME=$home XDG_CONFIG_HOME=$home/.config QT3D_RENDERER=opengl \
        xvfb-run -a -s "-screen 0 1440x900x24" "$program" "$@" --screenshot "$out"
    rm -rf "$home"
    [ -s "$out" ] || { echo "no picture in $out" >&2; exit 1; }
    echo "wrote $out"
}

shot docs/screenshot-main.png examples/classic.yaml --play --after 4
shot docs/design-map.png examples/classic.yaml --design-map --after 8
shot docs/presentation.png examples/classic.yaml --present --play --after 5
shot docs/teaching-window.png examples/classic.yaml --seek 0.75 --after 3
QT3D_RENDERER=opengl xvfb-run -a -s "-screen 0 1440x900x24" build/bin/doc_pictures examples docs
