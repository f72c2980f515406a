#!/usr/bin/env bash
# Runs a command on an X server of its own, of the given size, with a window
# manager (openbox) framing its windows, as a user's desktop does.
# Usage: under_window_manager.sh WIDTHxHEIGHT COMMAND [ARGS...]
set -euo pipefail
if [ "${1:-}" = --inside ]; then
    shift
    openbox >/dev/null 2>&1 &
    wm=$!
    trap 'kill "$wm" 2>/dev/null || true' EXIT
    sleep 1
    "$@"
    exit
fi
size=$1
shift
command -v openbox >/dev/null || { echo "openbox is missing (Debian: openbox)"; exit 1; }
exec xvfb-run -a -s "-screen 0 ${size}x24" bash "$0" --inside "$@"
