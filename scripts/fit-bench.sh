#!/usr/bin/env bash
# planter-fit's speed: a 10-minute field recording at 100 Hz (planter-sim, the field scenario
# on 36 m) with every channel analysed. Prints planter-fit's summary; its last line is the
# wall time and the ratio to one nominal simulation pass. The goal is under 30 s.
# Usage: scripts/fit-bench.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=$build/fit-bench
mkdir -p "$out"
sed -e "s|\.\./boards|$root/boards|; s|\.\./models|$root/models|" \
    -e "s|^distance_m = .*|distance_m = 36.0|" -e "s|^name = .*|name = \"fit-bench\"|" \
    "$root/scenarios/zhangqiu-field.toml" >"$out/fit-bench.toml"
"$build/sim/planter-sim" run "$out/fit-bench.toml" --out "$out/run" >/dev/null
rows=$(($(grep -vc '^#' "$out/run/recording.csv") - 1))
echo "recording: $rows rows at 100 Hz ($((rows / 6000)) min)"
"$build/apps/planter-fit/planter-fit" "$out/run/recording.csv" --out "$out/fit"
