#!/usr/bin/env bash
# The lockstep real-time factor as a user meets it: `planter-sim run` on the field scenario,
# with everything it writes (recording.csv, seedlings.csv, summary.json, report.html), three
# times; each run prints its own factor (simulated time over the simulation's wall time). The
# median is printed last, with the goal (issue 30).
# Usage: bench/run_realtime_factor.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
sim=$build/apps/planter-sim/planter-sim
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
factors=()
for i in 1 2 3; do
  line=$("$sim" run "$root/scenarios/zhangqiu-field.toml" --out "$work/run-$i" | grep "x real time")
  echo "run $i: $(sed -E "s/^distance +//" <<<"$line")"
  factors+=("$(sed -E 's/.* ([0-9]+)x real time.*/\1/' <<<"$line")")
done
median=$(printf '%s\n' "${factors[@]}" | sort -n | sed -n 2p)
echo "planter-sim run real-time factor (zhangqiu-field, with its outputs): ${median}x real time (goal >= 2000x)"
