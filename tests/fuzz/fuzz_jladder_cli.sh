#!/usr/bin/env bash
# The command line under abuse: jladder run, export, validate and reach with
# seeded random choices of options, absurd values and awkward output paths
# (the scene itself, a link to it, one file for two outputs, a full disk, a
# directory, a missing directory). Whatever comes, jladder must
#   - end by itself (no hang: each call has 60 s) and never by a signal,
#   - exit 0, 1 or 2, and say why on stderr when not 0,
#   - leave the scene it read as it was (and a link it read a link), and
#     every file that was there before a failed call as it was.
# Usage: fuzz_jladder_cli.sh JLADDER SOURCE_DIR WORK_DIR
# (JL_FUZZ_ITERATIONS=N for a longer run, JL_FUZZ_VERBOSE=1 to list the
# calls; the seed is fixed, so a failure comes back the same way).
set -u
jladder=$1 source=$2 work=$3
iterations=${JL_FUZZ_ITERATIONS:-300}
rm -rf "$work" && mkdir -p "$work" || exit 1
cd "$work" || exit 1
RANDOM=20261124

# The files a call may meet, as they are before each call.
inputs() {
    cp "$source/examples/classic.yaml" scene.yaml
    printf 'format: jacobs-ladder/1\nladder: {blocks: 4}\nscript:\n  - {at: 0, turn: {block: 0, by: 180deg, duration: 0.1}}\n' > small.yaml
    rm -f link.yaml && ln -s scene.yaml link.yaml
    echo "the old content" > precious.txt
    mkdir -p adir
}
sums() { sha256sum scene.yaml small.yaml precious.txt; }

# pick NAME CHOICES...: sets NAME to one of the choices. Not in a $(...):
# bash seeds RANDOM afresh in every subshell, and the run would not repeat.
pick() {
    local -n chosen=$1
    shift
    local choices=("$@")
    chosen=${choices[RANDOM % ${#choices[@]}]}
}

numbers=(0.05 0.3 0 -1 nan inf -inf 1e300 1e-300 abc "" 1e-6 0.1 100001 1e308 0x10 "1 2")
paths=(out.csv out.json scene.yaml link.yaml adir missing/dir/out.csv /dev/full /dev/null precious.txt "")
words=(rk4 dormand_prince45 rosenbrock_w explicit_euler rk5 "" RK4)
policies=(located end_of_step none)

failures=0
for ((i = 0; i < iterations; i++)); do
    inputs
    before=$(sums)
    pick command run run run export validate reach
    args=("$command")
    input=""
    case $command in
    run | export)
        pick input small.yaml small.yaml scene.yaml link.yaml missing.yaml adir /dev/null
        args+=("$input")
        for ((k = RANDOM % 5; k > 0; k--)); do
            case $((RANDOM % 9)) in
            0 | 1) pick v "${numbers[@]}" && args+=(--until "$v") ;;
            2) pick v "${numbers[@]}" && args+=(--step "$v") ;;
            3) pick v "${numbers[@]}" && args+=(--every "$v") ;;
            4) pick v "${numbers[@]}" && args+=(--tolerance "$v") ;;
            5) pick v "${words[@]}" && args+=(--integrator "$v") ;;
            6) pick v "${policies[@]}" && args+=(--event-policy "$v") ;;
            7) pick v "${paths[@]}" && args+=(--frames "$v") ;;
            8) pick v "${paths[@]}" && args+=(--events "$v") ;;
            esac
        done
        # Mostly a run that can finish quickly, so the outputs get written.
        ((RANDOM % 3)) && args+=(--until 0.2)
        ;;
    validate)
        pick input small.yaml scene.yaml link.yaml missing.yaml adir /dev/null precious.txt
        args+=("$input")
        ;;
    reach)
        pick v 4:6:2 4 2:3:1 0:5:1 4:1000000:1 a:b:c 6:4:1 "" && args+=(--blocks "$v")
        ((RANDOM % 2)) && pick v 6mm 6mm:12mm:6mm 1e300mm -1mm nanmm 6 && args+=(--thickness "$v")
        ((RANDOM % 2)) && pick v "${paths[@]}" && args+=(--csv "$v")
        ((RANDOM % 2)) && pick v "${paths[@]}" && args+=(--svg "$v")
        ((RANDOM % 3)) || { pick v 1 2 0 -1 1000000 x && args+=(--jobs "$v"); }
        if ((RANDOM % 3 == 0)); then
            pick input small.yaml scene.yaml missing.yaml adir
            args+=(--scene "$input")
        fi
        ;;
    esac
    # Now and then an option twice, or one that does not exist.
    ((RANDOM % 7)) || { pick v --until --frames --bogus -x -- && args+=("$v"); }

    [ -n "${JL_FUZZ_VERBOSE:-}" ] && echo "$i: jladder ${args[*]}"
    input_sum=""
    [ -f "$input" ] && input_sum=$(sha256sum < "$input")
    timeout -k 5 60 "$jladder" "${args[@]}" > stdout.txt 2> stderr.txt
    rc=$?
    problem=""
    if ((rc == 124 || rc == 137)); then problem="did not finish within 60 s"
    elif ((rc > 2)); then problem="exit status $rc (a signal or a crash)"
    elif ((rc != 0)) && [ ! -s stderr.txt ]; then problem="exit status $rc without a word on stderr"
    elif [ -n "$input_sum" ] && [ "$(sha256sum < "$input" 2> /dev/null)" != "$input_sum" ]; then problem="the scene it read changed"
    elif [ "$input" = link.yaml ] && [ ! -L link.yaml ]; then problem="the link it read was replaced by a file"
    elif ((rc != 0)) && [ "$(sums)" != "$before" ]; then problem="a failed call changed a file that was there"
    fi
    if [ -n "$problem" ]; then
        echo "iteration $i: $problem: jladder ${args[*]}" >&2
        head -c 600 stderr.txt >&2
        ((failures++))
    fi
    rm -rf out.csv out.json missing ./*.partial* 2>/dev/null
done
echo "$iterations command lines, $failures failures"
((failures == 0))
