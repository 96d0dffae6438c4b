#!/usr/bin/env bash
# Installs every Debian 12 package the project needs (idempotent) and builds into build/.
# Usage: scripts/setup.sh [build-dir] [extra cmake args...]
# PLANTER_BUILD_TARGETS="planter-sim ..." builds only those (the main job needs one program,
# not the 200 targets of tests, fuzzers and benchmarks).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
shift || true
packages=(g++ cmake ninja-build clang-format libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
          libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev libboost-dev libceres-dev
          pkg-config libgpiod-dev libsocketcan-dev systemd rt-tests
          can-utils python3-can clang libclang-rt-14-dev libjs-dygraphs chromium
          libcpp-httplib-dev chromium-driver python3-selenium help2man xz-utils
          libgps-dev gpsd gpsd-clients)
"$root/scripts/apt-install.sh" setup "${packages[@]}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
targets=()
# A man page's target exists only where help2man could make it (cmake/man_pages.cmake).
known=$(cmake --build "$build" --target help)
for t in ${PLANTER_BUILD_TARGETS:-}; do
  if [[ $t == *-man ]] && ! grep -q "^$t:" <<<"$known"; then
    echo "setup: no $t (no help2man here): the program is built without its man page" >&2
    continue
  fi
  targets+=(--target "$t")
done
cmake --build "$build" -j "$(nproc)" "${targets[@]}"
