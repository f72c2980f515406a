#!/usr/bin/env bash
# jladder reach as a user meets it: a design map written as CSV and SVG, the
# same bytes whatever the number of threads; bad axes refused with a message.
# Usage: jladder_reach.sh JLADDER [SOURCE_DIR] WORK_DIR
set -u
source "$(cd "$(dirname "$0")" && pwd)/expect.sh" "$@"

for jobs in 1 2; do
    "$jladder" reach --blocks 4:8:2 --thickness 6mm:12mm:6mm --jobs $jobs --csv map$jobs.csv --svg map$jobs.svg \
        2>err.txt || fail "reach --jobs $jobs: exit $? ($(head -c 300 err.txt))"
done
cmp -s map1.csv map2.csv || fail "the CSV depends on --jobs"
cmp -s map1.svg map2.svg || fail "the SVG depends on --jobs"
[ "$(head -1 map1.csv)" = "blocks,thickness [m],hinges,reached,mean_time_between_flips [s],flips_elsewhere_until_stop,events_until_stop,quick_row_until_stop,stopped_at [s],stopped_by,failure" ] ||
    fail "CSV header: $(head -1 map1.csv)"
[ "$(wc -l <map1.csv)" = 7 ] || fail "6 designs wanted, got: $(cat map1.csv)"
grep -q "^6,0.012,5,5," map1.csv || fail "the classic design (6 blocks, 12 mm) should ripple through its 5 hinges: $(cat map1.csv)"
# It stops once its ripple is at the bottom; run whole, every design runs
# its 1 + 0.2 N s, with the same reach and mean time between flips.
grep -q "^6,0.012,5,5,.*,bottom,$" map1.csv || fail "the classic design should stop at the bottom: $(cat map1.csv)"
"$jladder" reach --blocks 4:8:2 --thickness 6mm:12mm:6mm --whole-runs --csv whole.csv 2>err.txt ||
    fail "reach --whole-runs: exit $? ($(head -c 300 err.txt))"
[ "$(cut -d, -f9,10 whole.csv | sort -u | tr '\n' ' ')" = "1.8,end 2.2,end 2.6,end stopped_at [s],stopped_by " ] ||
    fail "whole runs should all run to their end: $(cut -d, -f1,9,10 whole.csv | tr '\n' ' ')"
[ "$(cut -d, -f1-5 whole.csv)" = "$(cut -d, -f1-5 map1.csv)" ] || fail "whole runs reach otherwise: $(cat whole.csv)"
grep -q "<svg" map1.svg && grep -q "block thickness (mm)" map1.svg || fail "the SVG has no map or no axis title"

# Each value of an axis is the number a scene file holding it as text reads:
# 9 mm is 0.009 m, not 9 x 0.001 or 1 mm + 8 x 1 mm in doubles
# (0.009000000000000001).
"$jladder" reach --blocks 4:4:1 --thickness 8mm:10mm:1mm --csv units.csv 2>err.txt || fail "8 to 10 mm: exit $?"
[ "$(cut -d, -f2 units.csv | tr '\n' ' ')" = "thickness [m] 0.008 0.009 0.01 " ] ||
    fail "thickness values not as a scene file holds them: $(cut -d, -f2 units.csv | tr '\n' ' ')"

# Bad axes: refused with a message, nothing written.
bad() {
    "$jladder" reach "$@" --csv bad.csv >out.txt 2>err.txt
    local got=$?
    [ "$got" = 2 ] || fail "exit $got, wanted 2: reach $*"
    [ -s err.txt ] || fail "no message for: reach $*"
    [ ! -e bad.csv ] || fail "bad.csv written for: reach $*"
}
bad --blocks 4:8
bad --blocks 8:4:1
bad --thickness 6kg:12mm:6mm
bad --blocks 4:8:2 --thickness 6mm:12mm:6mm --width 40mm:50mm:10mm
bad --blocks 4:8:2 --jobs 0
bad --blocks 2:100000:1

# A failed write: a message naming the file and exit 1; both files or
# neither, so the SVG from before stays as it was when the CSV cannot be
# written; and standard output checked too.
echo "the old map" > whole.svg
"$jladder" reach --blocks 4:4:1 --svg whole.svg --csv no-such-dir/map.csv >out.txt 2>err.txt
got=$?
[ "$got" = 1 ] || fail "a CSV in a missing directory: exit $got, wanted 1"
grep -q "no-such-dir/map.csv" err.txt || fail "no message naming the CSV: $(cat err.txt)"
[ "$(cat whole.svg)" = "the old map" ] || fail "the SVG was replaced though the CSV beside it failed"
# An output that is the base scene, or both outputs one file: refused.
printf "format: jacobs-ladder/1\nladder: {blocks: 4}\n" > base.yaml
"$jladder" reach --blocks 4:4:1 --scene base.yaml --csv base.yaml >out.txt 2>err.txt
[ $? = 2 ] && grep -q "destroy the scene" err.txt || fail "--csv over the base scene was not refused: $(cat err.txt)"
"$jladder" reach --blocks 4:4:1 --csv same.out --svg same.out >out.txt 2>err.txt
[ $? = 2 ] && grep -q "name the same file" err.txt || fail "--csv and --svg as one file were not refused: $(cat err.txt)"
if [ -w /dev/full ]; then
    "$jladder" reach --blocks 4:4:1 >/dev/full 2>err.txt
    got=$?
    [ "$got" = 1 ] || fail "CSV to a full disk: exit $got, wanted 1"
    grep -q "standard output" err.txt || fail "no message for a full disk: $(cat err.txt)"
fi
ls ./*.partial-* >/dev/null 2>&1 && fail "a temporary file was left behind: $(ls)"

# One axis: a line of designs.
"$jladder" reach --blocks 4:6:2 --csv line.csv 2>err.txt || fail "one axis: exit $?"
[ "$(wc -l <line.csv)" = 3 ] || fail "one axis: $(cat line.csv)"

[ "$failures" = 0 ] && echo "all reach checks passed"
exit "$failures"
