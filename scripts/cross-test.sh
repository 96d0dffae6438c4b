#!/usr/bin/env bash
# Cross builds for the controller boards: installs Debian's cross compilers, qemu-user and the
# :arm64/:armhf libraries (multiarch), then for each board preset builds planterd, planter-can
# and the unit tests, runs the unit tests under qemu-user, makes the .deb and checks it, and
# prints the stripped size of planterd. Usage: scripts/cross-test.sh [board...]; with no
# board, every board under boards/ whose toolchain is a cross one. The triple and the Debian
# architecture come from the board's toolchain file (cmake/toolchains/<toolchain>.cmake):
# adding a board is adding its folder.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
sudo_cmd=""
[ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"

# [board] toolchain of a board, and a set(NAME value) of a toolchain file.
toolchain_of() { sed -n 's/^toolchain *= *"\([^"]*\)".*/\1/p' "boards/$1/board.toml" | head -1; }
toolchain_value() { sed -n "s/^set($2 \([^ )]*\))/\1/p" "cmake/toolchains/$1.cmake" | head -1; }
presets=("$@")
if [ ${#presets[@]} -eq 0 ]; then
  for d in boards/*/; do
    b=$(basename "$d")
    [ "$(toolchain_of "$b")" != native ] && presets+=("$b")
  done
fi
declare -A arch triple
for p in "${presets[@]}"; do
  tc=$(toolchain_of "$p")
  arch[$p]=$(toolchain_value "$tc" PLANTER_DEB_ARCH)
  triple[$p]=$(toolchain_value "$tc" PLANTER_TRIPLE)
  if [ -z "${arch[$p]}" ] || [ -z "${triple[$p]}" ]; then
    echo "cross-test: board $p: toolchain '$tc' names no PLANTER_DEB_ARCH or PLANTER_TRIPLE" >&2
    exit 2
  fi
done
# No libgps-dev here: its multiarch libsystemd0 and liblzma5 must match the host's versions
# exactly, which a mirror between point releases cannot always give (seen: "held broken
# packages"); a cross planterd goes without gpsd and says so (hal/CMakeLists.txt).
libs=(libgpiod-dev libsocketcan-dev libtomlplusplus-dev libgtest-dev libgmock-dev pkgconf)
# help2man makes the man pages the packages carry (run under qemu-user: cmake/man_pages.cmake).
wanted=(qemu-user binutils-multiarch help2man)
for p in "${presets[@]}"; do
  a=${arch[$p]}
  dpkg --print-foreign-architectures | grep -qx "$a" || $sudo_cmd dpkg --add-architecture "$a"
  wanted+=("crossbuild-essential-$a")
  for l in "${libs[@]}"; do wanted+=("$l:$a"); done
done
scripts/apt-install.sh cross "${wanted[@]}"

# The operator's console: Debian's cpp-httplib of the board's architecture and the libraries
# it links, downloaded (cached in the build directory) and unpacked into a private sysroot.
# apt cannot install them beside the host's (Multi-Arch: same wants one version for all, and
# this machine's mirror has served the boards' architectures older versions than the host's).
# A download that fails is said, and that board is built without the console.
sysroot_of() { echo "$root/build-$1/console-sysroot"; }
console_sysroot() {  # console_sysroot BOARD ARCH: prints the cmake options, or nothing
  local dir a=$2 pkgs=() p
  dir=$(sysroot_of "$1")
  for p in libcpp-httplib-dev libcpp-httplib0.11 libssl-dev libssl3 libbrotli-dev libbrotli1 \
           zlib1g-dev zlib1g; do pkgs+=("$p:$a"); done
  if [ ! -f "$dir/ready" ]; then
    rm -rf "$dir" && mkdir -p "$dir/debs"
    if ! (cd "$dir/debs" && apt-get download -qq "${pkgs[@]}" >"$dir/download.log" 2>&1); then
      echo "cross: NO CONSOLE for board $1: apt-get download ${pkgs[*]} failed:" >&2
      sed 's/^/    /' "$dir/download.log" >&2
      return 0
    fi
    for d in "$dir"/debs/*.deb; do dpkg-deb -x "$d" "$dir/root"; done
    touch "$dir/ready"
  fi
  local lib
  lib=$(ls "$dir"/debs/libcpp-httplib0.11_*.deb | head -1)
  local version
  version=$(dpkg-deb -f "$lib" Version)
  echo "-DPLANTER_CONSOLE_SYSROOT=$dir/root"
  echo "-DPLANTER_CONSOLE_DEPENDS=$(dpkg-deb -f "$lib" Package) (>= ${version%-*})"
}

for p in "${presets[@]}"; do
  a=${arch[$p]}
  echo "== cross build for board $p ($a, ${triple[$p]})"
  mapfile -t console_opts < <(console_sysroot "$p" "$a")
  cmake -S . -B "build-$p" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPLANTER_BOARD="$p" \
    -DPLANTER_BUILD_BENCH=OFF -DCMAKE_UNITY_BUILD=ON "${console_opts[@]}" >/dev/null
  cmake --build "build-$p" -j "$(nproc)" --target planterd planter-can planter_unit_tests \
    planter_can_tests planterd_service_tests planter_dem_tests fuzz_can_frame fuzz_text_inputs fuzz_board_file fuzz_nmea \
    planterd-man planter-can-man
  echo "== unit tests of $p under qemu-user"
  (cd "build-$p" && ctest -L unit -j "$(nproc)" --output-on-failure | tail -3)
  (cd "build-$p" && cpack -G DEB >/dev/null)
  deb=$(ls -t "build-$p"/planter_*_"$a".deb | head -1)
  scripts/package-test.sh "$deb" "$a"
  if "${triple[$p]}-readelf" -d "build-$p/apps/planterd/planterd" | grep -q 'libcpp-httplib'; then
    # It loads under qemu-user with the libraries the board's Depends bring (here the sysroot's).
    libs_dir="$(sysroot_of "$p")/root"
    LD_LIBRARY_PATH="$libs_dir/usr/lib/${triple[$p]}:$libs_dir/lib/${triple[$p]}" \
      "$(toolchain_value "$(toolchain_of "$p")" PLANTER_QEMU)" "build-$p/apps/planterd/planterd" --help \
      >/dev/null || { echo "cross: $p: planterd with the console does not start under qemu-user" >&2; exit 1; }
    echo "cross: $p: planterd serves the operator's console (links libcpp-httplib; starts under qemu-user)"
  else
    echo "cross: $p: planterd has NO operator's console (no cpp-httplib for $a: docs/planterd.md, the operator's console)"
  fi
done
for p in "${presets[@]}"; do
  scripts/bench-size.sh "build-$p/apps/planterd/planterd" "${triple[$p]}"
done
