#!/usr/bin/env bash
# How long a newcomer waits for the first result's build: planter-sim alone (what
# scripts/field-trial.sh builds), configured and built from nothing in a scratch directory, on
# this machine's cores. The packages are taken as installed (scripts/setup.sh installs them).
# Prints the figure last, with its goal (issue 29: under 3 minutes on an idle 2-core machine).
# Usage: scripts/bench-field-trial-build.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
start=$(date +%s.%N)
cmake -S "$root" -B "$scratch" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$scratch" -j "$(nproc)" --target planter-sim >/dev/null
end=$(date +%s.%N)
awk -v s="$start" -v e="$end" -v n="$(nproc)" 'BEGIN {
  printf "field-trial build from a clean tree: %.0f s wall on %d cores (goal < 180 s)\n", e - s, n }'
