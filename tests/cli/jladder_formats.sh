#!/usr/bin/env bash
# What jladder writes is read by a strict reader (check_formats.py): JSON in
# UTF-8 without bare NaN, CSV by RFC 4180 with every row as wide as its
# header and no bare nan, SVG that is well-formed XML, whatever the names
# and titles it was given; and a title XML cannot hold is refused.
# Usage: jladder_formats.sh JLADDER SOURCE_DIR WORK_DIR
set -u
check="python3 $(cd "$(dirname "$0")" && pwd)/check_formats.py"
source "$(cd "$(dirname "$0")" && pwd)/expect.sh" "$@"

# strict KIND FILE...: each file read by the strict reader.
strict() {
    $check "$@" 2>check.txt || fail "$(cat check.txt)"
}

cp "$source/examples/classic.yaml" scene.yaml

# A scene whose name is not UTF-8: the summary is still UTF-8 JSON.
cp scene.yaml $'\xff-scene.yaml'
expect 0 "$jladder" run $'\xff-scene.yaml' --until 0.3 --events events.json --frames frames.csv
cp out.txt summary.json
strict json summary.json events.json
strict numbers frames.csv
expect 0 "$jladder" export scene.yaml --until 0.3 --energy energy.csv --csv poses.csv
strict numbers energy.csv poses.csv

# The design map: a title with what XML escapes is written escaped; one
# with what XML cannot hold is refused before any cell is computed.
expect 0 "$jladder" reach --blocks 4:6:2 --jobs 1 --csv map.csv --svg map.svg --title 'a < b & "c" ]]> café'
strict csv map.csv
strict xml map.svg
for title in $'a\x01b\x1bc' $'caf\xe9' $'a\xef\xbf\xbfb'; do
    expect 2 "$jladder" reach --blocks 4:6:2 --jobs 1 --csv bad.csv --svg bad.svg --title "$title"
    grep -q -- "--title" err.txt || fail "the refused title is not named: $(head -c 300 err.txt)"
    [ -e bad.svg ] && fail "an SVG was written with the title $(printf %q "$title")" && rm -f bad.svg
done

# The benchmark's tables: methods hold commas, and some quantities are not
# measured in a quick run.
expect 0 "$jladder" bench --quick --only models --out bench --report bench/models.md
expect 0 "$jladder" bench --quick --only stability --out bench --report bench/stability.md
strict csv bench/models.csv bench/stability.csv
grep -q '"rk4, merged, chain solver"' bench/models.csv || fail "models.csv lost the method 'rk4, merged, chain solver'"

# bench's last line names its directory and report.
expect 0 "$jladder" bench --quick --only models --out $'\xff-bench' --report $'\xff-bench/models.md'
strict json out.txt

if [ $failures -gt 0 ]; then
    echo "$failures failures" >&2
    exit 1
fi
echo "all passed"
