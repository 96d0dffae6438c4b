#!/usr/bin/env bash
# Every board names a toolchain that exists; a board that names a missing toolchain, a bad GPIO
# line or a duplicate node ID gets one clear message naming file, line and key.
set -uo pipefail
cmake=$1
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
for b in "$root"/boards/*/board.toml; do
  out=$("$cmake" -DBOARD_FILE="$b" -P "$root/cmake/board_toolchain.cmake" 2>&1) ||
    { echo "FAIL $b: $out"; fail=1; }
done
sed 's/toolchain = "aarch64-linux-gnu"/toolchain = "aarch64-linux-musl"/' \
  "$root/boards/rpi4-canhat/board.toml" >"$work/bad-toolchain.toml"
out=$("$cmake" -DBOARD_FILE="$work/bad-toolchain.toml" -P "$root/cmake/board_toolchain.cmake" 2>&1)
rc=$?
out=$(tr -s ' \n' ' ' <<<"$out")  # CMake wraps its messages
if [ $rc -ne 0 ] && grep -q "bad-toolchain.toml:5: 'board.toolchain': 'aarch64-linux-musl' has no" <<<"$out"; then
  echo "ok   missing toolchain: $(grep -o "bad-toolchain.toml:5.*" <<<"$out" | head -1)"
else
  echo "FAIL missing toolchain not reported: $out"; fail=1
fi
# A toolchain file whose cross compiler is not installed says what installs it (issue 29: a cross
# configure gave CMake's raw "aarch64-linux-gnu-g++ not found"). A triple no machine here has.
printf 'set(PLANTER_TRIPLE riscv64-unknown-none)\nset(PLANTER_DEB_ARCH riscv64)\nset(PLANTER_QEMU qemu-riscv64)\ninclude(%s/cmake/toolchains/debian-multiarch.cmake)\n' \
  "$root" >"$work/missing.cmake"
mkdir -p "$work/src" && printf 'cmake_minimum_required(VERSION 3.25)\nproject(x CXX)\n' >"$work/src/CMakeLists.txt"
out=$("$cmake" -S "$work/src" -B "$work/build" -DCMAKE_TOOLCHAIN_FILE="$work/missing.cmake" 2>&1)
rc=$?
out=$(tr -s ' \n' ' ' <<<"$out")
if [ $rc -ne 0 ] && grep -q "no riscv64-unknown-none-g++ on PATH: .*scripts/cross-test.sh installs it" <<<"$out"; then
  echo "ok   cross compiler missing: says scripts/cross-test.sh installs it"
else
  echo "FAIL a missing cross compiler is not said with what installs it: $out"; fail=1
fi
exit $fail
