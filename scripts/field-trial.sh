#!/usr/bin/env bash
# The main job: set up, build, and run the simulated Zhangqiu field trial.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh" "$root/build" >/dev/null
"$root/build/sim/planter-sim" run "$root/scenarios/zhangqiu-field.toml" --out "${1:-$root/out/zhangqiu-field}"
