#!/usr/bin/env bash
# planter-fit on a kept console recording of a clean machine (28 s of the field scenario at four
# times real time, `planter-sim live`, recorded from the console as
# fit_explains_a_console_recording_test.py does): the clamp is held at one force, so its law is
# undetermined, and its nominal fit is hard to converge: every start runs n to its bound (0.9)
# with k_c and x0 trading along a valley into it. With Ceres' projected line search, the fit
# stopped at a held-out RMS of 1.41 N; without it, 3.35 N, and a play and a hysteresis were
# named; with the search kept only for fits from a rough start, a relaxation at its range's edge
# took the misfit (docs/performance.md). Every channel must be "no significant mismatch":
# nothing was hidden. And the clamp's nominal must reach the noise (held-out RMS within 10 % of
# it): the law fits this recording to its noise (0.99 N) once the bound is held.
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
# The clamp's line: "held-out RMS A -> B (noise N)".
read -r held noise < <(sed -nE 's/^clamp +clamp_force .*held-out RMS ([0-9.e+-]+) -> [0-9.e+-]+ \(noise ([0-9.e+-]+)\).*/\1 \2/p' "$work/summary.txt") || true
[ -n "${held:-}" ] || { echo "FAIL: no clamp_force line with its held-out RMS and noise"; exit 1; }
awk -v h="$held" -v n="$noise" 'BEGIN { exit !(h <= 1.1 * n) }' ||
  { echo "FAIL: the clamp's nominal stopped at a held-out RMS of $held N, noise $noise N (10 % over it at most)"; exit 1; }
echo "PASS: the kept console recording, 6 of 6 channels clean; the clamp's held-out RMS $held N, noise $noise N"
