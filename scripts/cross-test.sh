#!/usr/bin/env bash
# Cross builds for the controller boards: installs Debian's cross compilers, qemu-user and the
# :arm64/:armhf libraries (multiarch), then for each board preset builds planterd, planter-can
# and the unit tests, runs the unit tests under qemu-user, makes the .deb and checks it, and
# prints the stripped size of planterd. Usage: scripts/cross-test.sh [preset...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
presets=("$@")
[ ${#presets[@]} -eq 0 ] && presets=(rpi4-canhat bbb-dcan)
sudo_cmd=""
[ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"

declare -A arch=([rpi4-canhat]=arm64 [bbb-dcan]=armhf)
declare -A triple=([arm64]=aarch64-linux-gnu [armhf]=arm-linux-gnueabihf)
libs=(libgpiod-dev libsocketcan-dev libtomlplusplus-dev libgtest-dev libgmock-dev pkgconf)
wanted=(qemu-user binutils-multiarch)
for p in "${presets[@]}"; do
  a=${arch[$p]}
  dpkg --print-foreign-architectures | grep -qx "$a" || $sudo_cmd dpkg --add-architecture "$a"
  wanted+=("crossbuild-essential-$a")
  for l in "${libs[@]}"; do wanted+=("$l:$a"); done
done
scripts/apt-install.sh cross "${wanted[@]}"

for p in "${presets[@]}"; do
  a=${arch[$p]}
  echo "== cross build for board $p ($a, ${triple[$a]})"
  cmake --preset "$p" >/dev/null
  cmake --build --preset "$p" -j "$(nproc)" --target planterd planter-can planter_unit_tests \
    planter_can_tests planterd_service_tests planter_dem_tests fuzz_can_frame fuzz_text_inputs fuzz_board_file
  echo "== unit tests of $p under qemu-user"
  ctest --preset "$p" -L unit -j "$(nproc)" | tail -3
  (cd "build-$p" && cpack -G DEB >/dev/null)
  deb=$(ls -t "build-$p"/planter_*_"$a".deb | head -1)
  scripts/package-test.sh "$deb" "$a"
done
for p in "${presets[@]}"; do
  scripts/bench-size.sh "build-$p/apps/planterd/planterd" "${triple[${arch[$p]}]}"
done
