#!/bin/sh
# /init of the test VM: loads CAN and gpio-sim, mounts the host's root read-only (9p) and the
# run directory writable at the same path, brings up vcan0 and a gpio-sim chip, then runs
# $planter_out/guest-cmd.sh chrooted into the host's root. Its exit code goes back in
# $planter_out/guest-exit. planter_out and planter_show (host paths, ':'-separated, that must
# stay visible, e.g. a checkout under /tmp) come from the kernel command line.
export PATH=/bin:/sbin
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
for m in virtio_pci 9pnet_virtio 9p can can-raw can-dev vcan configfs gpio-sim overlay; do
  modprobe "$m" 2>/dev/null || echo "guest: modprobe $m failed"
done
say() { echo "guest: $*"; }
finish() {
  echo "$1" > "/host$planter_out/guest-exit"
  sync
  poweroff -f
}
mount -t 9p -o trans=virtio,version=9p2000.L,ro,msize=262144 host /host || { say "9p host mount failed"; poweroff -f; }
# The guest's writable scratch (tmpfs on /tmp and /run) would hide host paths under them: keep
# a view of the host's own tree and bind the paths the run needs back on top of the scratch.
mkdir -p /hostview && mount -o bind /host /hostview
mount -t tmpfs tmp /host/tmp
mount -t tmpfs run /host/run
for p in $(echo "$planter_show" | tr ':' ' '); do
  case "$p" in
    /tmp/* | /run/*)
      mkdir -p "/host$p" && mount -o bind "/hostview$p" "/host$p" || say "cannot show $p" ;;
  esac
done
mkdir -p "/host$planter_out" 2>/dev/null
mount -t 9p -o trans=virtio,version=9p2000.L,msize=262144 out "/host$planter_out" ||
  { say "9p out mount failed"; poweroff -f; }
mount -o bind /proc /host/proc
mount -o bind /sys /host/sys
mount -o bind /dev /host/dev
mount -t configfs none /host/sys/kernel/config || say "configfs mount failed"
mkdir -p /host/dev/pts /host/dev/shm
mount -t devpts devpts /host/dev/pts
mount -t tmpfs shm /host/dev/shm

in_host() { chroot /host /bin/sh -c "$*"; }
in_host "ip link set lo up" || say "loopback setup failed"  # planterd's console in the tests
in_host "ip link add dev vcan0 type vcan && ip link set vcan0 txqueuelen 100 && ip link set up vcan0" ||
  { say "vcan0 setup failed"; finish 90; }
C=/host/sys/kernel/config/gpio-sim/planter
mkdir "$C" "$C/bank0" && echo 8 > "$C/bank0/num_lines" && echo planter-sim > "$C/bank0/label" &&
  echo 1 > "$C/live" || { say "gpio-sim setup failed"; finish 91; }
gpio_dev=$(cat "$C/dev_name")
gpio_chip=$(cat "$C/bank0/chip_name")
say "vcan0 up; gpio-sim $gpio_dev/$gpio_chip (label planter-sim)"
in_host "cd '$planter_out' && PLANTER_GPIO_CHIP='$gpio_chip' \
  PLANTER_GPIO_SYSFS='/sys/devices/platform/$gpio_dev/$gpio_chip' HOME=/tmp \
  /bin/sh '$planter_out/guest-cmd.sh'"
finish $?
