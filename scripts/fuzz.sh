#!/usr/bin/env bash
# Builds the fuzz targets with clang + libFuzzer (address and undefined sanitizers) and runs
# each for a bounded time, starting from the checked-in corpus. A crash fails the script and
# leaves the input in build-fuzz/findings/ (add it to tests/fuzz/corpus/<target>/ once fixed).
# Usage: scripts/fuzz.sh [seconds-per-target] [build-dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build=${2:-$root/build-fuzz}
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPLANTER_FUZZ=ON -DPLANTER_BUILD_TESTS=OFF -DPLANTER_BUILD_BENCH=OFF >/dev/null
targets=(can_frame text_inputs board_file recording device_frames config_files)
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/fuzz_}"
mkdir -p "$build/findings"
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t"
  mkdir -p "$corpus"
  cp -n "$root/tests/fuzz/corpus/$t/"* "$corpus/" 2>/dev/null || true
  echo "== fuzz_$t for ${seconds} s"
  (cd "$build/findings" && "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=5 \
    -rss_limit_mb=2048 -print_final_stats=1 "$corpus" 2>&1 | grep -E "^(#[0-9]+.*DONE|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY)" ) || {
    echo "fuzz_$t found a failure; inputs in $build/findings"
    exit 1
  }
done
