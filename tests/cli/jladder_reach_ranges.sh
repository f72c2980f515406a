#!/usr/bin/env bash
# jladder reach takes for each axis only the values a scene file may hold:
# a value outside the scene format's range, a blocks count that is not
# whole, an axis with too many values or a design the scene loader refuses
# is refused before any cell runs, with the axis and the allowed range
# named, rather than clamped, rounded or run into a row that looks like an
# answer. Counts (--jobs) are whole numbers, written as such.
# Usage: jladder_reach_ranges.sh JLADDER WORK_DIR
set -u
source "$(cd "$(dirname "$0")" && pwd)/expect.sh" "$@"

# refused MESSAGE ARGS...: exit 2, MESSAGE on stderr, no map written; quick
# (a check, not a run: well under the timeout's seconds).
refused() {
    local message=$1
    shift
    expect 2 timeout 20 "$jladder" reach "$@" --csv map.csv
    expect_message "$message"
    [ ! -e map.csv ] || fail "map.csv written for: reach $*"
    rm -f map.csv
}

refused "blocks 1 is not allowed: the scene format takes a whole number from 2 to 100000" --blocks 1:1:1
refused "blocks -5 is not allowed" --blocks -5:-5:1
refused "blocks 2.5 is not allowed" --blocks 2.5:2.5:1
refused "blocks 1e+09 is not allowed" --blocks 1e9:1e9:1
refused "^jladder reach: --length 1e-9:1e-9:1: block length 1e-09 m is out of range: the scene format takes a number in \[0.0001, 100\] (m)" \
    --length 1e-9:1e-9:1
refused "block thickness 0 m is out of range" --thickness 0:0:1
refused "block thickness -0.012 m is out of range" --thickness -12mm:-12mm:1mm
refused "block thickness 1e+300 m is out of range" --thickness 1e300:1e300:1
refused "block width -1 m is out of range" --width -1:-1:1
refused "density 0 kg/m^3 is out of range: the scene format takes a number in \[1, 100000\]" --density 0:0:1
refused "hinge damping -1 N m s is out of range" --hinge_damping -1:-1:1
refused "hinge damping 1e+300 N m s is out of range" --hinge_damping 1e300:1e300:1
refused "turn duration 0 s is out of range: the scene format takes a number in \[0.001, 100000\] (s)" \
    --turn_duration 0:0:1
refused "turn duration -1 s is out of range" --turn_duration -1:-1:1
refused "turn duration 1e-09 s is out of range" --turn_duration 1e-9:1e-9:1
refused "turn duration 1e+06 s is out of range" --turn_duration 1e6:1e6:1
# Every value is checked, not only the ends: 2, 3.5, 5 blocks.
refused "blocks 3.5 is not allowed" --blocks 2:5:1.5
# Too many values is said as such, not as "no values".
refused "gives 999999999 values, more than the 200" --blocks 2:1e9:1
refused "more than the 200" --thickness 1mm:12mm:1e-300mm
refused "gives no values: FROM must be at most TO" --blocks 8:4:1
# A design the scene loader refuses: the base scene holds block 5, which a
# ladder of 4 blocks does not have.
printf "format: jacobs-ladder/1\nladder: {blocks: 6, held: [5]}\n" >held5.yaml
refused "with blocks 4 the scene is not valid" --blocks 4:8:2 --scene held5.yaml

# Counts are whole numbers as written.
for jobs in 2x 1e3 1.0 "" " 2" 0 257; do
    refused "--jobs takes a whole number from 1 to 256, not '$jobs'" --blocks 4:4:1 --jobs "$jobs"
done

# Values within the ranges still run, at both ends of the turn duration's.
expect 0 "$jladder" reach --blocks 2:2:1 --turn_duration 1ms:1ms:1 --jobs 1 --csv ok.csv
grep -q "^2,0.001,1," ok.csv || fail "a 2-block ladder turned in 1 ms: $(cat ok.csv)"

[ "$failures" = 0 ] && echo "all reach range checks passed"
exit "$failures"
