#!/usr/bin/env bash
# A new user's window fits the screen under a window manager: at 1440 x 900
# and at 1280 x 720 (a common projector size), with openbox framing it, the
# whole frame (title bar, menus, the status bar at the bottom) is on screen.
# The geometry is read from the X server (xwininfo), not from Qt, and a
# picture of each screen is left in the test's folder to look at.
#
# Usage: window_fits_screen.sh PROGRAM SCENE OUTDIR
set -euo pipefail

if [ "${1:-}" = --inside ]; then
    # On the display xvfb-run made for one size: openbox, then the program.
    program=$2 scene=$3 size=$4 out=$5
    home=$(mktemp -d)
    trap 'kill "${app:-}" "${wm:-}" 2>/dev/null || true; rm -rf "$home"' EXIT
    openbox >/dev/null 2>&1 &
    wm=$!
    sleep 1
    HOME=$home XDG_CONFIG_HOME=$home/.config QT3D_RENDERER=opengl "$program" "$scene" >/dev/null 2>&1 &
    app=$!
    # The frame openbox puts round the window: the largest viewable child of the root.
    frame=""
    for _ in $(seq 1 100); do
        sleep 0.2
        best=0
        for id in $(xwininfo -root -children | awk '/^ +0x/ {print $1}'); do
            # A window listed a moment ago may be gone (a tooltip, a splash):
            # skip it rather than let `set -e` end the test.
            info=$(xwininfo -id "$id" 2>/dev/null) || continue
            grep -q "IsViewable" <<<"$info" || continue
            x=$(awk '/Absolute upper-left X/ {print $4}' <<<"$info")
            y=$(awk '/Absolute upper-left Y/ {print $4}' <<<"$info")
            w=$(awk '/  Width:/ {print $2}' <<<"$info")
            h=$(awk '/  Height:/ {print $2}' <<<"$info")
            if [ $((w * h)) -gt "$best" ]; then best=$((w * h)) frame="$x $y $w $h"; fi
        done
        # Framed and fitted: wait for the geometry to hold still.
        if [ -n "$frame" ] && [ "$frame" = "${last:-}" ] && [ "$best" -gt 100000 ]; then break; fi
        last=$frame
    done
    [ -n "$frame" ] || { echo "$size: no window appeared"; exit 1; }
    import -window root "$out/window-$size.png" 2>/dev/null || true
    read -r x y w h <<<"$frame"
    W=${size%x*} H=${size#*x}
    echo "$size: the framed window is ${w} x ${h} at ($x, $y)"
    if [ "$x" -lt 0 ] || [ "$y" -lt 0 ] || [ $((x + w)) -gt "$W" ] || [ $((y + h)) -gt "$H" ]; then
        echo "$size: the window does not fit the screen (its bottom edge at $((y + h)), the screen's at $H)"
        exit 1
    fi
    exit 0
fi

program=$1 scene=$2 out=$3
mkdir -p "$out"
for tool in openbox xwininfo; do
    command -v "$tool" >/dev/null || { echo "$tool is missing (Debian: openbox, x11-utils)"; exit 1; }
done
failed=0
for size in 1440x900 1280x720; do
    xvfb-run -a -s "-screen 0 ${size}x24" bash "$0" --inside "$program" "$scene" "$size" "$out" || failed=1
done
[ "$failed" = 0 ] && echo "the window fits at every size"
exit "$failed"
