#!/usr/bin/env bash
# A run that fails or crawls says what limits its step: the stiffest mode
# (what makes it, where, how fast), and the integrator that copes; it never
# sends the user to look for held blocks in a scene that holds none, nor
# asks for a smaller step or a tighter tolerance already at its floor. The
# rates checked are the textbook ones: sqrt(k/m) for a spring on a mass,
# c/I for air damping on a block of inertia m (l^2 + t^2) / 12.
# Usage: jladder_diagnoses.sh JLADDER SOURCE_DIR WORK_DIR
set -u
source "$(cd "$(dirname "$0")" && pwd)/expect.sh" "$@"

# A 1 mg particle on a 1e7 N/m spring: omega = sqrt(1e7 / 1e-6) = 3.16e6 rad/s,
# a period of 2 pi / omega = 1.99e-6 s. Nothing is held.
printf 'format: jacobs-ladder/1\nparticles:\n  - {name: p, mass: 0.000001, position: [0, -0.1]}\nsprings:\n  - {a: {body: world}, b: {body: p}, stiffness: 10000000, rest_length: 0.05}\n' >spring.yaml
expect 1 "$jladder" run spring.yaml --until 1
expect_message "the stiffest mode is the spring 0 (1e+07 N/m on 1e-06 kg): 3.16e+06 rad/s, a period of 1.99e-06 s"
expect_message "rosenbrock_w"
! grep -q "held blocks" err.txt || fail "a scene without held blocks is sent to look for them: $(cat err.txt)"
# The step at its floor: not "try a smaller step".
expect 1 "$jladder" run spring.yaml --until 1 --step 1e-6
expect_message "the step 1e-06 s is at its floor and still too large here: the stiffest mode is the spring 0"
! grep -q "try a smaller step" err.txt || fail "a smaller step is asked for below the floor: $(cat err.txt)"

# The classic with the most air damping: blocks of 0.01944 kg, inertia
# 0.01944 (0.06^2 + 0.012^2) / 12 = 6.07e-6 kg m^2, so 1000 N m s decays
# their turning at 1000 / 6.07e-6 = 1.65e8 per s.
{ cat "$source/examples/classic.yaml"; echo 'damping: {linear: 1000, angular: 1000}'; } >damped.yaml
expect 1 "$jladder" run damped.yaml --until 2.5
expect_message "the stiffest mode is air damping 1e+03 N m s on body [0-9]* (inertia 6.07e-06 kg m^2): it decays at 1.65e+08 per s"

# A ladder 1e4 m from the origin asked for pins closed to 1e-15 m: below
# the rounding of its coordinates (2.2e-16 x 1.4e4 m, a few 1e-12 m).
cat >far.yaml <<'YAML'
format: jacobs-ladder/1
ladder:
  blocks: 6
  initial: {kind: fold_angles, poses: [{block: 0, position: [9999, 9999]}], fold_angles: [3.1, 3.1, 3.1, 3.1, 3.1]}
solver: {projection_tolerance: 1e-15}
YAML
expect 1 "$jladder" run far.yaml --until 1
expect_message "the projection tolerance 1e-15 m is below the rounding of coordinates near 1e+04 m"
! grep -q "held blocks" err.txt || fail "the far ladder blames held blocks: $(cat err.txt)"

# A run that would take far longer than the time it simulates says so
# (here interrupted once it has: after 3 s of a run of many minutes), with
# its step and the mode that sets it. Twelve blocks of alternating masses
# run about 300 times slower than real time (measured on the CI machine), well
# past the warning's 100 times (six blocks ran at 84 times: no warning).
sed 's/density: 600, color: "#c8a26b"}/mass: 0.000001}\n  overrides: [{index: 1, mass: 1000000}, {index: 3, mass: 1000000}, {index: 5, mass: 1000000}, {index: 7, mass: 1000000}, {index: 9, mass: 1000000}, {index: 11, mass: 1000000}]/; s/^  blocks: 6/  blocks: 12/' \
    "$source/examples/classic.yaml" >alternating.yaml
grep -q "overrides" alternating.yaml || fail "the alternating-mass scene was not made"
timeout -s INT 6 "$jladder" run alternating.yaml --until 2.5 >out.txt 2>err.txt
expect_message "jladder run: slow: t = .* s after [0-9]* s, so the 2.5 s asked for would take about .* more. The step is .* s; the stiffest mode is the rocking of body"
expect_message "try it"
# A run at its own pace says nothing of the kind.
expect 0 "$jladder" run "$source/examples/classic.yaml" --until 2.5
! grep -q "slow:" err.txt || fail "the classic was called slow: $(cat err.txt)"

[ "$failures" = 0 ] && echo "all diagnosis checks passed"
exit "$failures"
