#!/usr/bin/env bash
# The clamp that grips each stem under its own ceiling against the best constant force (issue
# 50): `planter-sim montecarlo --grip` over 32 draws of every model value, on the field's stems
# and on stems of 5-15 mm. Each prints its share of draws where the per-stem clamp's damage is at
# most half the best constant force's (goal 90 %), and the same for a clamp told each stem's true
# peak (a bound no sensor reaches: what knowing each stem's strength would buy); the 5-15 mm
# per-stem line is printed last.
# Usage: bench/grip_benchmark.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
sim=$build/apps/planter-sim/planter-sim
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Each run prints the bound (a clamp told each stem's true peak) and then the per-stem line.
field=$("$sim" montecarlo "$root/scenarios/zhangqiu-field.toml" --runs 32 --grip \
  --out "$work/field" 2>/dev/null | tail -n 2)
thick=$("$sim" montecarlo "$root/scenarios/zhangqiu-field.toml" --runs 32 --grip \
  --stems-mm 5-15 --out "$work/thick" 2>/dev/null | tail -n 2)
echo "field's stems, $(head -n 1 <<<"$field")"
echo "stems of 5-15 mm, $(head -n 1 <<<"$thick")"
echo "field's stems: $(tail -n 1 <<<"$field")"
echo "stems of 5-15 mm: $(tail -n 1 <<<"$thick")"
