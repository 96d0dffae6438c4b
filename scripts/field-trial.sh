#!/usr/bin/env bash
# The main job: set up, build, and run the simulated Zhangqiu field trial.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
log="$root/build/field-trial-setup.log"
mkdir -p "$root/build"
echo "field-trial: installing what is missing and building in build/ (the first time takes" \
  "a few minutes; log: build/field-trial-setup.log)" >&2
if ! "$root/scripts/setup.sh" "$root/build" >"$log" 2>&1; then
  echo "field-trial: the setup or the build failed; the end of $log:" >&2
  tail -n 30 "$log" >&2
  exit 1
fi
echo "field-trial: running the simulated Zhangqiu field trial (30 m)" >&2
"$root/build/sim/planter-sim" run "$root/scenarios/zhangqiu-field.toml" --out "${1:-$root/out/zhangqiu-field}"
