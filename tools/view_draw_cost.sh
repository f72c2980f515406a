#!/usr/bin/env bash
# The 3-D view's drawing cost on a 10,000-block classic ladder, each case
# run REPEAT times (default 3), each in a process of its own on an X server
# of its own (1440 x 900), as docs/desktop-performance.md reports it.
# Usage: tools/view_draw_cost.sh BUILD_DIR [REPEAT] [EXTRA ARGS for view_draw_cost]
set -euo pipefail
build=${1:?build directory}
repeat=${2:-3}
shift $(( $# < 2 ? $# : 2 ))
export QT3D_RENDERER=opengl
uptime
for r in $(seq "$repeat"); do
    for view in "" --close; do
        for ribbons in "" --hide-ribbons; do
            for mode in "" --reshow; do
                xvfb-run -a -s "-screen 0 1440x900x24" "$build/bin/view_draw_cost" $view $ribbons $mode "$@"
            done
        done
    done
done
uptime
