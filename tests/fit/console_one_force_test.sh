#!/usr/bin/env bash
# planter-fit on a kept console recording of a clean machine (28 s of the field scenario at four
# times real time, `planter-sim live`, recorded from the console as
# fit_explains_a_console_recording_test.py does): the clamp is held at one force, so its law is
# undetermined, and its nominal fit is hard to converge from its starts. With Ceres' projected
# line search off, its nominal fit stopped at a held-out RMS of 3.35 N (noise 0.99) and a play
# and a hysteresis were named; with the search kept only for fits from a rough start, a
# relaxation at its range's edge took the misfit (docs/performance.md). Every channel must be
# "no significant mismatch": nothing was hidden.
set -euo pipefail
tool=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
xz -dc "$src/tests/fit/data/console-28s-one-force.csv.xz" >"$work/console.csv"
"$tool" "$work/console.csv" --out "$work/fit" >"$work/summary.txt"
cat "$work/summary.txt"
# Counted on the printed summary, as fit_explains_the_simulator_test.sh counts it.
channels=$(grep -cE "^(ground|disc drive|clamp|depth) " "$work/summary.txt")
clean=$(grep -cE "^(ground|disc drive|clamp|depth) .* no significant mismatch " "$work/summary.txt")
[ "$channels" -eq 6 ] && [ "$clean" -eq 6 ] ||
  { echo "FAIL: $clean of $channels channels are 'no significant mismatch' on the kept console recording"; exit 1; }
echo "PASS: the kept console recording, 6 of 6 channels clean"
