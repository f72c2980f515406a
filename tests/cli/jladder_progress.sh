#!/usr/bin/env bash
# Long work shows how far it is on stderr, for a person at a terminal:
# run and export the simulated time, rate and time left, reach the cells
# done, bench the studies done; nothing of it when stderr is a file or a
# pipe, and nothing with --quiet. A run that will write more than 1 GiB of
# frames says so before it goes on. `script` (util-linux) gives the
# command a terminal.
# Usage: jladder_progress.sh JLADDER SOURCE_DIR WORK_DIR
set -u
source "$(cd "$(dirname "$0")" && pwd)/expect.sh" "$@"
command -v script >/dev/null || {
    echo "script (util-linux) is not installed"
    exit 1
}

cp "$source/examples/classic.yaml" scene.yaml
# A run of about a second or more: long enough for the line to be drawn.
run=("$jladder" run scene.yaml --until 3 --step 2e-5 --integrator rk4 --frames frames.csv)
sed "s/^duration: .*/duration: 3\nsolver: {integrator: rk4, step: 2e-5}/" scene.yaml >fine.yaml
export_=("$jladder" export fine.yaml --until 3 --csv poses.csv)
reach=("$jladder" reach --blocks 2:3:1 --jobs 1 --csv map.csv)
mkdir examples && cp "$source/examples/pendulum.yaml" examples/
bench=("$jladder" bench --quick --only examples --examples examples --out bench --report bench/report.md)

# on_terminal FILE COMMAND...: COMMAND's output, as its terminal shows it, in FILE.
on_terminal() {
    local file=$1
    shift
    script -q -e -c "$(printf '%q ' "$@")" /dev/null >"$file" </dev/null || fail "on a terminal: $*: exit $?"
}

on_terminal tty_run.txt "${run[@]}"
grep -q "of 3 s simulated, .* s per s, about .* left" tty_run.txt || fail "run: no progress line on a terminal: $(head -c 300 tty_run.txt)"
on_terminal tty_export.txt "${export_[@]}"
grep -q "of 3 s simulated" tty_export.txt || fail "export: no progress line on a terminal"
on_terminal tty_reach.txt "${reach[@]}"
grep -q "2 of 2 cells done" tty_reach.txt || fail "reach: no progress line on a terminal: $(head -c 300 tty_reach.txt)"
on_terminal tty_bench.txt "${bench[@]}"
grep -q "\[0 of 1 done, .* so far\] examples at default settings" tty_bench.txt ||
    fail "bench: no progress on a terminal: $(head -c 300 tty_bench.txt)"

# --quiet on a terminal, and stderr to a file or a pipe: none of it.
on_terminal quiet_run.txt "${run[@]}" --quiet
on_terminal quiet_export.txt "${export_[@]}" --quiet
on_terminal quiet_reach.txt "${reach[@]}" --quiet
on_terminal quiet_bench.txt "${bench[@]}" --quiet
for f in quiet_run quiet_export quiet_reach; do
    ! grep -q "simulated\|cells done" $f.txt || fail "$f: a progress line despite --quiet: $(head -c 300 $f.txt)"
done
! grep -q "done, .* so far" quiet_bench.txt || fail "bench: progress despite --quiet"
expect 0 "${run[@]}"
! grep -q "simulated" err.txt || fail "run: a progress line in a file: $(head -c 300 err.txt)"
"${export_[@]}" 2>&1 | cat >piped.txt
! grep -q "simulated" piped.txt || fail "export: a progress line in a pipe"
expect 0 "${reach[@]}"
! grep -q "cells done" err.txt || fail "reach: a progress line in a file: $(head -c 300 err.txt)"
expect 0 "${bench[@]}"
! grep -q "done, .* so far" err.txt || fail "bench: progress in a file"

# More than 1 GiB of frames: said before the run goes on (here it is
# interrupted at once: the warning is what is checked).
timeout -s INT 0.5 "$jladder" run scene.yaml --until 100000 --every 1e-3 --frames big.csv >out.txt 2>err.txt
rm -f big.csv.partial
expect_message "this run will write about .* GiB of frames"
expect 0 "$jladder" run scene.yaml --until 1 --frames small.csv
! grep -q "GiB" err.txt || fail "a small run warned of its size: $(cat err.txt)"

[ "$failures" = 0 ] && echo "all progress checks passed"
exit "$failures"
