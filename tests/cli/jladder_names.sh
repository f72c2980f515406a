#!/usr/bin/env bash
# Every name an output is given is resolved as the writer will resolve it:
# a name that cannot be resolved (a link chain beyond the kernel's 40 links,
# a link loop) is refused before anything is written, and what a run that
# stopped early computed never lands on a file the run did not create.
# Usage: jladder_names.sh JLADDER SOURCE_DIR WORK_DIR
set -u
source "$(cd "$(dirname "$0")" && pwd)/expect.sh" "$@"

# same FILE ORIGINAL: FILE unchanged; put back if not, for the next case.
same() {
    cmp -s "$1" "$2" || {
        fail "$1 changed"
        cp "$2" "$1"
    }
}

cp "$source/examples/classic.yaml" pristine.yaml
cp pristine.yaml scene.yaml

# chain NAME TARGET COUNT: NAME -> link COUNT -> ... -> link 1 -> TARGET.
chain() {
    local p=$2
    for i in $(seq "$3"); do
        ln -s "$p" "$1.$i"
        p=$1.$i
    done
    ln -s "$p" "$1"
}

# A chain of 46 links to the scene: the kernel gives up at 40, so the name
# cannot be resolved, and the scene must not be written through it.
chain long.csv scene.yaml 45
for command in "run scene.yaml --until 0.2 --frames long.csv" "export scene.yaml --until 0.2 --csv long.csv"; do
    # shellcheck disable=SC2086
    expect 2 "$jladder" $command
    expect_message "Too many levels of symbolic links"
    same scene.yaml pristine.yaml
done
expect 2 "$jladder" reach --blocks 4:6:2 --scene scene.yaml --csv long.csv
expect_message "Too many levels of symbolic links"
same scene.yaml pristine.yaml

# The same chain to another output: refused, not one output over the other.
echo '["keep"]' >keep.json && cp keep.json keep-before.json
chain keep-link.csv keep.json 45
expect 2 "$jladder" run scene.yaml --until 0.2 --frames keep-link.csv --events keep.json
expect_message "Too many levels of symbolic links"
same keep.json keep-before.json

# A chain the kernel follows (30 links) is the scene, and said so.
chain short.csv scene.yaml 29
expect 2 "$jladder" run scene.yaml --until 0.2 --frames short.csv
expect_message "is the scene file"
same scene.yaml pristine.yaml

# A link loop is refused and stays a link.
ln -s loop2 loop1 && ln -s loop1 loop2
expect 2 "$jladder" run scene.yaml --until 0.2 --frames loop1
expect_message "Too many levels of symbolic links"
[ -L loop1 ] || fail "the link loop1 was replaced by a file"

# A run that fails keeps what it computed in FILE.partial only when no
# such file exists: here FILE.partial is the scene itself.
cp pristine.yaml frames.partial
expect 1 "$jladder" run frames.partial --until 2 --integrator explicit_euler --step 0.01 --frames frames
same frames.partial pristine.yaml
kept=$(ls frames.partial-* 2>/dev/null | head -1)
[ -n "$kept" ] && [ "$(head -1 "$kept")" = "t [s],block,x [m],y [m],angle [rad]" ] || fail "the failed run's frames are not kept"
expect_message "$kept"

# ... or another output, left as it was by the same failed run.
rm -f frames.partial-*
echo old >a && echo '["old events"]' >a.partial && cp a.partial a-before.partial
expect 1 "$jladder" run scene.yaml --until 2 --integrator explicit_euler --step 0.01 --frames a --events a.partial
same a.partial a-before.partial
[ "$(cat a)" = old ] || fail "a failed run replaced a"

# A full file system (here the file-size limit) ends the kept frames on a
# whole row, not a torn one.
rm -f f.csv*
(
    cp pristine.yaml scene.yaml
    trap '' XFSZ
    ulimit -f 64
    "$jladder" run scene.yaml --until 2.5 --frames f.csv --every 0.0001 >out.txt 2>err.txt
)
[ -e f.csv.partial ] || fail "no f.csv.partial after a write past the size limit ($(head -c 300 err.txt))"
awk -F, 'NF != 5 { print "line " NR ": " $0; bad = 1 } END { exit bad }' f.csv.partial >torn.txt ||
    fail "f.csv.partial has a torn row: $(head -1 torn.txt)"
[ -z "$(tail -c 1 f.csv.partial)" ] || fail "f.csv.partial ends in a torn row: $(tail -1 f.csv.partial)"

if [ $failures -gt 0 ]; then
    echo "$failures failures" >&2
    exit 1
fi
echo "all passed"
