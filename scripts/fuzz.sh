#!/usr/bin/env bash
# Builds the fuzz targets with clang + libFuzzer (address and undefined sanitizers) and runs
# each for a bounded time (one target per core at a time), starting from the checked-in corpus. A crash fails the script and
# leaves the input in build-fuzz/findings/ (add it to tests/fuzz/corpus/<target>/ once fixed).
# Usage: scripts/fuzz.sh [seconds-per-target] [build-dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
build=${2:-$root/build-fuzz}
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPLANTER_FUZZ=ON -DPLANTER_BUILD_TESTS=OFF -DPLANTER_BUILD_BENCH=OFF -DCMAKE_UNITY_BUILD=ON >/dev/null
targets=(can_frame text_inputs board_file recording device_frames config_files console_request
         console_connection nmea sbatch_script)
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/fuzz_}"
mkdir -p "$build/findings"
# One target per core at a time: each still fuzzes for its full time, on its own core.
fuzz_one() {
  local t=$1 corpus="$build/corpus/$1"
  mkdir -p "$corpus"
  cp -n "$root/tests/fuzz/corpus/$t/"* "$corpus/" 2>/dev/null || true
  (cd "$build/findings" && "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=5 \
    -rss_limit_mb=2048 -print_final_stats=1 "$corpus") >"$build/findings/fuzz_$t.log" 2>&1
}
report() {  # report TARGET RC: its summary lines, and a failure said once
  echo "== fuzz_$1 for ${seconds} s"
  grep -E "^(#[0-9]+.*DONE|stat::number_of_executed_units|==[0-9]+==ERROR|SUMMARY)" \
    "$build/findings/fuzz_$1.log" || true
  if [ "$2" -ne 0 ]; then
    echo "fuzz_$1 found a failure; inputs in $build/findings, its log in fuzz_$1.log"
    failed=1
  fi
}
failed=0
parallel=$(nproc)
for ((i = 0; i < ${#targets[@]}; i += parallel)); do
  batch=("${targets[@]:i:parallel}")
  pids=()
  for t in "${batch[@]}"; do
    fuzz_one "$t" &
    pids+=($!)
  done
  for k in "${!batch[@]}"; do
    rc=0
    wait "${pids[$k]}" || rc=$?
    report "${batch[$k]}" "$rc"
  done
done
exit $failed
