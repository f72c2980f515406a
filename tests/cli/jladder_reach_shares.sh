#!/usr/bin/env bash
# A design map computed in shares (jladder reach --cells K/N, one per
# machine) and joined (--merge) is the map one machine computes, byte for
# byte, CSV and SVG; shares of different maps, a share missing or given
# twice are refused with a message. The shares run as docs/ripple-reach.md
# shows: with GNU parallel when it is installed, else one after another.
# Usage: jladder_reach_shares.sh JLADDER WORK_DIR
set -u
source "$(cd "$(dirname "$0")" && pwd)/expect.sh" "$@"

# A small map: 3 x 2 cells of short ladders (a few seconds in all).
axes=(--blocks 2:4:1 --thickness 8mm:12mm:4mm)
expect 0 "$jladder" reach "${axes[@]}" --csv whole.csv --svg whole.svg --title "six designs"

# Four shares of six cells (1, 2, 1 and 2 cells), each on its own.
if command -v parallel >/dev/null 2>&1; then
    parallel --will-cite "$jladder" reach "${axes[@]}" --jobs 1 --cells {}/4 --csv share{}.csv ::: 1 2 3 4 2>err.txt ||
        fail "GNU parallel: $(head -c 300 err.txt)"
else
    for k in 1 2 3 4; do
        expect 0 "$jladder" reach "${axes[@]}" --jobs 1 --cells $k/4 --csv share$k.csv
    done
fi
[ "$(head -1 share1.csv)" = "map,share,cell,blocks,thickness [m],hinges,reached,mean_time_between_flips [s],flips_elsewhere_until_stop,events_until_stop,quick_row_until_stop,stopped_at [s],stopped_by,failure" ] ||
    fail "share header: $(head -1 share1.csv)"
rows=0
for k in 1 2 3 4; do rows=$((rows + $(wc -l <share$k.csv) - 1)); done
[ "$rows" = 6 ] || fail "the four shares hold $rows cells, not the map's 6"

# Joined in any order: the same bytes as the one-machine map.
expect 0 "$jladder" reach --merge share3.csv share1.csv share4.csv share2.csv --csv joined.csv --svg joined.svg \
    --title "six designs"
cmp -s whole.csv joined.csv || fail "the joined CSV differs from the one-machine map: $(diff whole.csv joined.csv | head -5)"
cmp -s whole.svg joined.svg || fail "the joined SVG differs from the one-machine map"
# And to standard output.
expect 0 "$jladder" reach --merge share1.csv share2.csv share3.csv share4.csv
cmp -s whole.csv out.txt || fail "the joined CSV on standard output differs from the one-machine map"

# Refused: a share missing, a share twice, a share of another map, nothing joined.
refused() {
    local message=$1
    shift
    expect 1 "$jladder" reach --merge "$@" --csv bad.csv
    expect_message "$message"
    [ ! -e bad.csv ] || fail "bad.csv written for: --merge $*"
}
refused "share 4 of 4 is missing" share1.csv share2.csv share3.csv
refused "share1.csv and share1.csv are both share 1 of 4" share1.csv share1.csv share2.csv share3.csv share4.csv
cp share2.csv copy2.csv
refused "share2.csv and copy2.csv are both share 2 of 4" share1.csv share2.csv copy2.csv share3.csv share4.csv
expect 0 "$jladder" reach --blocks 2:4:1 --thickness 8mm:16mm:8mm --jobs 1 --cells 1/4 --csv other1.csv
refused "give the shares of one map" share1.csv share2.csv share3.csv share4.csv other1.csv
printf "format: jacobs-ladder/1\nladder: {blocks: 4, block: {density: 500}}\nscript:\n  - {at: 0.2, turn: {block: 0, by: 180deg}}\n" >light.yaml
expect 0 "$jladder" reach "${axes[@]}" --scene light.yaml --jobs 1 --cells 4/4 --csv light4.csv
refused "give the shares of one map" share1.csv share2.csv share3.csv light4.csv
# Whole runs count other events: a share of them is another map's.
expect 0 "$jladder" reach "${axes[@]}" --whole-runs --jobs 1 --cells 4/4 --csv whole4.csv
refused "give the shares of one map" share1.csv share2.csv share3.csv whole4.csv
refused "is not a share of a map" whole.csv
head -2 share2.csv >short2.csv
refused "short2.csv has 1 cells; share 2 of 4 has 2" share1.csv short2.csv share3.csv share4.csv

# Shares asked for wrongly: refused before any cell runs.
for cells in 0/4 5/4 2x/4 1/0 1.0/4 4; do
    expect 2 "$jladder" reach "${axes[@]}" --cells "$cells" --csv bad.csv
    expect_message "--cells takes K/N"
done
expect 2 "$jladder" reach "${axes[@]}" --cells 1/7 --csv bad.csv
expect_message "the map has only 6 cells"
expect 2 "$jladder" reach "${axes[@]}" --cells 1/4 --svg bad.svg
expect_message "give --svg to --merge"
expect 2 "$jladder" reach --merge share1.csv --csv share1.csv
expect_message "is the share share1.csv"
[ ! -e bad.csv ] && [ ! -e bad.svg ] || fail "a refused share wrote a file"

[ "$failures" = 0 ] && echo "all reach share checks passed"
exit "$failures"
