#!/usr/bin/env bash
# Stripped size of a planterd build for a board (the flash budget: 2 MB). Prints the figure last.
# Usage: scripts/bench-size.sh PATH/TO/planterd TRIPLE
set -euo pipefail
bin=$1
triple=$2
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
"$triple-strip" -o "$tmp" "$bin"
size=$(stat -c %s "$tmp")
unstripped=$(stat -c %s "$bin")
awk -v s="$size" -v u="$unstripped" -v t="$triple" 'BEGIN {
  printf "planterd %s: %d bytes unstripped, stripped %d bytes = %.2f MB (goal < 2 MB: %.0f %% of it)\n",
         t, u, s, s / 1e6, 100 * s / 2e6 }'
