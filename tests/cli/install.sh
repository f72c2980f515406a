#!/usr/bin/env bash
# An install puts the programs, the lessons (the examples), the icon and the
# desktop entry where a desktop expects them, and the installed program finds
# its lessons there. Usage: install.sh BUILD_DIR PREFIX WITH_UI(ON|OFF)
set -u
build=$1
prefix=$2
ui=$3
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null || { echo "FAIL: cmake --install"; exit 1; }
failures=0
need() { [ -e "$prefix/$1" ] || { echo "FAIL: $1 not installed"; failures=$((failures + 1)); }; }
need bin/jladder
need share/jacobs-ladder/examples/classic.yaml
if [ "$ui" = ON ]; then
    need bin/jacobsladder
    need share/icons/hicolor/scalable/apps/jacobsladder.svg
    need share/applications/jacobsladder.desktop
    found=$(cd / && QT_QPA_PLATFORM=offscreen "$prefix/bin/jacobsladder" --lessons-directory 2>/dev/null)
    case "$found" in
        "$(cd "$prefix" && pwd -P)/share/jacobs-ladder/examples") ;;
        *) echo "FAIL: the installed program finds its lessons in '$found'"; failures=$((failures + 1)) ;;
    esac
fi
[ $failures -eq 0 ] && echo "all passed"
exit $((failures > 0))
