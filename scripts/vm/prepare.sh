#!/usr/bin/env bash
# Prepares a small VM with a real CAN and GPIO kernel (see ../shared/notes/microvm-hil.md):
# Debian's own 6.1 amd64 kernel, its CAN modules, gpio-sim built out of tree from Debian's
# linux-source, and a busybox initramfs. Everything is cached under CACHE; a second run
# only checks the cache.
# Usage: scripts/vm/prepare.sh CACHE
set -euo pipefail
cache=${1:?usage: prepare.sh CACHE}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)

fail() { echo "vm-prepare: $*" >&2; exit 1; }
step() { echo "vm-prepare: $*"; }

sudo_cmd=""
[ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
host_packages=(qemu-system-x86 busybox-static cpio kmod can-utils gpiod iproute2 make gcc)
"$(dirname "$0")/../apt-install.sh" vm-prepare "${host_packages[@]}" ||
  fail "apt-get install ${host_packages[*]} failed"

# The newest kernel ABI apt offers: the one the linux-image-amd64 meta-package points at.
if [ ! -f "$cache/abi" ]; then
  abi=$(apt-cache depends linux-image-amd64 2>/dev/null |
        sed -n 's/.*Depends: linux-image-\(6\.1\.0-[0-9]*\)-amd64$/\1/p' | head -1)
  [ -n "$abi" ] || fail "apt offers no linux-image-6.1.0-*-amd64 (is the package index reachable?)"
  echo "$abi" > "$cache/abi"
fi
abi=$(cat "$cache/abi")
kver="$abi-amd64"
img_dir="$cache/image"
if [ ! -f "$img_dir/boot/vmlinuz-$kver" ]; then
  step "downloading linux-image-$kver"
  (cd "$cache" && apt-get download -qq "linux-image-$kver" >/dev/null 2>&1) ||
    fail "apt-get download linux-image-$kver failed"
  rm -rf "$img_dir"
  dpkg-deb -x "$cache"/linux-image-"$kver"_*.deb "$img_dir"
  rm -f "$cache"/linux-image-"$kver"_*.deb
fi
if ! dpkg-query -W -f='${Status}' "linux-headers-$kver" 2>/dev/null | grep -q "install ok installed"; then
  step "installing linux-headers-$kver"
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends \
    "linux-headers-$kver" >/dev/null || fail "apt-get install linux-headers-$kver failed"
fi

# gpio-sim: not in Debian's kernel; build it from Debian's own source of the same series.
gpio_sim="$cache/gpio-sim/gpio-sim.ko"
if [ ! -f "$gpio_sim" ]; then
  src_dir="$cache/gpio-sim"
  rm -rf "$src_dir" && mkdir -p "$src_dir"
  step "downloading linux-source-6.1"
  (cd "$cache" && apt-get download -qq linux-source-6.1 >/dev/null 2>&1) ||
    fail "apt-get download linux-source-6.1 failed"
  dpkg-deb -x "$cache"/linux-source-6.1_*.deb "$cache/src"
  rm -f "$cache"/linux-source-6.1_*.deb
  tarball=$(ls "$cache"/src/usr/src/linux-source-6.1.tar.* | head -1)
  [ -f "$tarball" ] || fail "linux-source-6.1 holds no tarball"
  step "extracting gpio-sim from $(basename "$tarball")"
  tar -xf "$tarball" -C "$src_dir" --strip-components=1 --wildcards \
    '*/drivers/gpio/gpio-sim.c' '*/drivers/gpio/gpiolib.h' '*/kernel/irq/irq_sim.c' ||
    fail "gpio-sim sources missing from $tarball"
  rm -rf "$cache/src"
  cp "$src_dir/drivers/gpio/gpio-sim.c" "$src_dir/drivers/gpio/gpiolib.h" "$src_dir/"
  # irq_to_desc is not exported to modules; generic_handle_irq does the same here.
  sed 's/handle_simple_irq(irq_to_desc(irqnum));/generic_handle_irq(irqnum);/' \
    "$src_dir/kernel/irq/irq_sim.c" > "$src_dir/irq_sim.c"
  grep -q 'generic_handle_irq(irqnum);' "$src_dir/irq_sim.c" ||
    fail "irq_sim.c changed upstream: the irq_to_desc patch no longer applies"
  cat > "$src_dir/Kbuild" <<'KBUILD'
obj-m := gpio-sim.o
gpio-sim-y := gpio-sim-main.o irq_sim.o
KBUILD
  mv "$src_dir/gpio-sim.c" "$src_dir/gpio-sim-main.c"
  step "building gpio-sim.ko against linux-headers-$kver"
  make -s -C "/usr/src/linux-headers-$kver" M="$src_dir" modules >"$src_dir/build.log" 2>&1 ||
    { tail -20 "$src_dir/build.log" >&2; fail "gpio-sim build failed (log: $src_dir/build.log)"; }
fi

# Initramfs: busybox, the modules with their dependency files, and the init script.
initrd="$cache/initrd.cpio.gz"
if [ ! -f "$initrd" ] || [ "$here/guest-init.sh" -nt "$initrd" ]; then
  step "building initramfs"
  root="$cache/initramfs"
  rm -rf "$root" && mkdir -p "$root"/{bin,sbin,proc,sys,dev,host,tmp,etc}
  cp /bin/busybox "$root/bin/busybox"
  for applet in sh mount umount modprobe insmod mkdir cat echo sleep poweroff chroot ls ip \
                sync reboot dmesg; do
    ln -sf busybox "$root/bin/$applet"
  done
  mods="$root/lib/modules/$kver"
  mkdir -p "$mods"
  srcmods="$img_dir/lib/modules/$kver"
  for m in virtio_pci virtio_pci_modern_dev virtio_pci_legacy_dev virtio_ring virtio \
           9pnet 9pnet_virtio 9p netfs fscache can can-raw can-dev vcan configfs overlay; do
    f=$(find "$srcmods" -name "$m.ko*" | head -1)
    [ -n "$f" ] || continue   # built into this kernel
    mkdir -p "$mods/$(dirname "${f#$srcmods/}")"
    cp "$f" "$mods/${f#$srcmods/}"
  done
  mkdir -p "$mods/extra" && cp "$gpio_sim" "$mods/extra/"
  cp "$srcmods"/modules.order "$srcmods"/modules.builtin* "$mods/" 2>/dev/null || true
  depmod -b "$root" "$kver" || fail "depmod failed"
  cp "$here/guest-init.sh" "$root/init" && chmod +x "$root/init"
  (cd "$root" && find . | cpio -o -H newc --quiet | gzip -1) > "$initrd.tmp"
  mv "$initrd.tmp" "$initrd"
fi
ln -sf "$img_dir/boot/vmlinuz-$kver" "$cache/vmlinuz"
step "ready: kernel $kver, gpio-sim, initramfs in $cache"
