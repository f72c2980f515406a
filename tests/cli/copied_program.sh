#!/usr/bin/env bash
# A copy of the desktop program, not installed, lists the lessons laid out
# around it (share/jacobs-ladder/examples beside its bin/), never those of the
# checkout it was built from. Usage: copied_program.sh JACOBSLADDER SOURCE_DIR WORK_DIR
set -u
source "$(cd "$(dirname "$0")" && pwd)/expect.sh" "$@"
program=$1
mkdir -p "$work/alone/bin" "$work/kit/bin" "$work/kit/share/jacobs-ladder/examples"
cp "$program" "$work/alone/bin/jacobsladder"
cp "$program" "$work/kit/bin/jacobsladder"
cp "$source/examples/pendulum.yaml" "$work/kit/share/jacobs-ladder/examples/"
# The folder a program would list its lessons from, started from elsewhere.
lessons() { (cd / && env -u JL_EXAMPLES QT_QPA_PLATFORM=offscreen "$1" --lessons-directory 2>/dev/null); }

found=$(lessons "$work/alone/bin/jacobsladder")
[ -z "$found" ] || fail "a copy with no lessons beside it lists those in '$found'"
found=$(lessons "$work/kit/bin/jacobsladder")
[ "$found" = "$(cd "$work/kit/share/jacobs-ladder/examples" && pwd -P)" ] ||
    fail "a copy with lessons beside it lists those in '$found'"
found=$(lessons "$program")
[ "$found" = "$(cd "$source/examples" && pwd -P)" ] || fail "the build's program lists the lessons in '$found'"
if [ $failures -gt 0 ]; then
    echo "$failures failures" >&2
    exit 1
fi
echo "all passed"
