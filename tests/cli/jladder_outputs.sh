#!/usr/bin/env bash
# jladder run/export must never destroy an input or an earlier output, never
# report success when something was not written, and keep what a run that
# stopped early computed. Usage: jladder_outputs.sh JLADDER SOURCE_DIR WORK_DIR
set -u
source "$(cd "$(dirname "$0")" && pwd)/expect.sh" "$@"

same() {
    cmp -s "$1" "$2" || fail "$1 changed"
}

cp "$source/examples/classic.yaml" scene.yaml
cp scene.yaml pristine.yaml
ln -s scene.yaml link.yaml
ln scene.yaml hard.yaml

# An output that is the scene, by name, link or hard link: refused, scene intact.
for option in --frames --events; do
    for name in scene.yaml ./scene.yaml link.yaml hard.yaml "$work/scene.yaml"; do
        expect 2 "$jladder" run scene.yaml --until 0.5 "$option" "$name"
        expect_message "is the scene file"
        same scene.yaml pristine.yaml
    done
done
expect 2 "$jladder" export scene.yaml --csv link.yaml
expect_message "is the scene file"
same scene.yaml pristine.yaml

# Two outputs in one file: refused before anything is written.
expect 2 "$jladder" run scene.yaml --until 0.5 --frames out.csv --events ./out.csv
expect_message "name the same file"
[ -e out.csv ] && fail "out.csv made by a refused run"
echo old >old.csv
ln -s old.csv old-link.csv
expect 2 "$jladder" export scene.yaml --csv old.csv --energy old-link.csv
expect_message "name the same file"
[ "$(cat old.csv)" = old ] || fail "old.csv changed by a refused export"

# A write that fails is a failure, said as such.
expect 1 "$jladder" run scene.yaml --until 0.5 --events /dev/full
expect_message "No space left"
expect 1 "$jladder" export scene.yaml --until 0.5 --csv /dev/full
expect_message "No space left"
"$jladder" run scene.yaml --until 0.5 >/dev/full 2>err.txt
[ $? = 1 ] || fail "a summary written to /dev/full is a success"
expect_message "cannot write the summary"
for command in run export reach validate bench; do
    "$jladder" "$command" --help >/dev/full 2>err.txt
    status=$?
    [ $status = 1 ] || fail "'$command --help' written to /dev/full exits $status"
    expect_message "cannot write the help"
done

# All outputs or none: when one cannot be written, the others stay as they
# were (here the events, through a link, would have replaced another scene).
cp scene.yaml other.yaml && ln -s other.yaml other-link.yaml
expect 1 "$jladder" run pristine.yaml --until 0.2 --events other-link.yaml --frames /dev/full
expect_message "No space left on device"
same other.yaml scene.yaml
[ -L other-link.yaml ] || fail "the link to the other scene was replaced by a file"
expect 1 "$jladder" run pristine.yaml --until 0.2 --events other-link.yaml --frames ""
expect_message "no file name given"
same other.yaml scene.yaml

expect 1 "$jladder" run scene.yaml --until 0.5 --frames no/such/dir/frames.csv
expect_message "no/such/dir"

# Options that would hang a run or fill the memory are refused, as the
# same values are in a scene file (docs/scene-format.md).
for args in "run scene.yaml --until 1 --step 1e-300" "run scene.yaml --until 1 --every 1e-300" \
            "run scene.yaml --until 1 --integrator dormand_prince45 --tolerance 1e-30" \
            "run scene.yaml --until 1e300" "export scene.yaml --until 1e300 --csv huge.csv" \
            "run scene.yaml --until 1 --step 0" "run scene.yaml --until nan" "run scene.yaml --until 1e999"; do
    # shellcheck disable=SC2086
    expect 2 timeout 20 "$jladder" $args
    expect_message "needs a number"
done
[ -e huge.csv ] && fail "a refused export made huge.csv"

# A good run replaces the old files whole and leaves nothing else behind;
# a link stays a link. Devices and the standard output are written directly.
echo old >frames.csv
echo old >events-target.json
ln -s events-target.json events.json
expect 0 "$jladder" run scene.yaml --until 0.5 --frames frames.csv --events events.json
[ "$(head -1 frames.csv)" = "t [s],block,x [m],y [m],angle [rad]" ] || fail "frames.csv not replaced"
[ -L events.json ] || fail "events.json is no longer a link"
[ "$(tail -1 events-target.json)" = "]" ] || fail "events not written through the link"
ls | grep -q partial && fail "temporaries left behind: $(ls | grep partial)"
expect 0 "$jladder" run scene.yaml --until 0.5 --events /dev/stdout --frames /dev/null
grep -q '"event":"lock"' out.txt || fail "events not written to the standard output"
grep -q '"failure":null' out.txt || fail "no summary after the events on the standard output"

# A run that fails leaves the old files and keeps what it computed beside
# them; its summary and events are still JSON that a strict parser reads
# (no bare nan or inf).
echo old >frames.csv
expect 1 "$jladder" run scene.yaml --until 2 --integrator explicit_euler --step 0.01 --frames frames.csv \
    --events events.json
[ "$(cat frames.csv)" = old ] || fail "a failed run replaced frames.csv"
[ "$(wc -l <frames.csv.partial)" -gt 10 ] || fail "a failed run kept nothing in frames.csv.partial"
expect_message "frames.csv.partial"
if command -v python3 >/dev/null; then
    strict='import json, sys
def refuse(word): raise ValueError(word)
for name in sys.argv[1:]:
    json.load(open(name), parse_constant=refuse)'
    python3 -c "$strict" out.txt events.json.partial || fail "the summary or the events are not strict JSON"
fi

# Interrupted (kill's default signal) and killed runs, long enough to be
# caught midway: the old file stays, what was computed is kept.
long_run() {
    "$jladder" run scene.yaml --until 100000 --frames frames.csv >out.txt 2>err.txt &
    pid=$!
    for _ in $(seq 100); do
        sleep 0.1
        [ "$(cat frames.csv.partial-* 2>/dev/null | wc -l)" -gt 100 ] && break
    done
}
echo old >frames.csv
rm -f frames.csv.partial*
long_run
kill -TERM $pid
wait $pid
status=$?
[ $status = 143 ] || fail "an interrupted run exits $status, not by its signal (143)"
[ "$(cat frames.csv)" = old ] || fail "an interrupted run replaced frames.csv"
[ "$(wc -l <frames.csv.partial)" -gt 100 ] || fail "an interrupted run kept nothing in frames.csv.partial"
grep -q '"failure":"interrupted by SIGTERM' out.txt || fail "the summary does not say the run was interrupted"
ls | grep -q 'partial-' && fail "temporaries left behind by an interrupted run"

rm -f frames.csv.partial*
long_run
kill -KILL $pid
wait $pid 2>/dev/null
[ "$(cat frames.csv)" = old ] || fail "a killed run replaced frames.csv"
[ "$(cat frames.csv.partial-* | wc -l)" -gt 100 ] || fail "a killed run left nothing of what it computed"

# A run ends at exactly the time asked for, whatever the integrator: the
# adaptive one used to stop a step past it (0.50008 s for --until 0.5).
for scene in "$source/examples/pendulum.yaml" scene.yaml; do
    expect 0 "$jladder" run "$scene" --until 0.5
    grep -q '"time":0.5,' out.txt || fail "a run to 0.5 s ended at $(grep -o '"time":[^,]*' out.txt) ($scene)"
done

# An adaptive integrator's steps are its error control's: the summary says
# so, with the range of the steps it chose (it once gave the engine's first
# try as both the smallest and the largest).
expect 0 "$jladder" run scene.yaml --until 1 --integrator dormand_prince45
steps=$(grep -o '"step":{"chosen_by":"error control","smallest":[^,]*,"largest":[^}]*}' out.txt)
smallest=$(echo "$steps" | sed 's/.*"smallest":\([^,]*\),.*/\1/')
largest=$(echo "$steps" | sed 's/.*"largest":\([^}]*\)}.*/\1/')
[ -n "$steps" ] && awk -v a="$smallest" -v b="$largest" 'BEGIN { exit !(a > 0 && a < b) }' ||
    fail "the adaptive run's step is not its error control's range: $(head -c 300 out.txt)"

if [ $failures -gt 0 ]; then
    echo "$failures failures" >&2
    exit 1
fi
echo "all passed"
