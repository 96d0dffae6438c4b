#!/usr/bin/env bash
# Runs a command inside the test VM (real vcan0 and a gpio-sim chip), with the host's
# binaries. The command runs in RUN_DIR (writable, shared with the host) with
# PLANTER_GPIO_CHIP and PLANTER_GPIO_SYSFS set; its exit code is this script's. PLANTER_VM_SHOW
# (host paths, ':'-separated) are kept visible in the guest even under /tmp or /run.
# Usage: scripts/vm/run.sh CACHE RUN_DIR TIMEOUT_S COMMAND...
set -euo pipefail
cache=${1:?usage: run.sh CACHE RUN_DIR TIMEOUT_S COMMAND...}
run_dir=${2:?}
timeout_s=${3:?}
shift 3
mkdir -p "$run_dir"
cache=$(cd "$cache" && pwd)
run_dir=$(cd "$run_dir" && pwd)
[ -f "$cache/vmlinuz" ] && [ -f "$cache/initrd.cpio.gz" ] ||
  { echo "vm-run: $cache is not prepared (run scripts/vm/prepare.sh $cache)" >&2; exit 1; }
rm -f "$run_dir/guest-exit"
printf '%q ' "$@" > "$run_dir/guest-cmd.sh"
echo >> "$run_dir/guest-cmd.sh"
# TCG, not KVM: nested KVM hangs on these machines (microvm-hil.md). Not -icount: with it
# QEMU 7.2 hangs bringing up a second vCPU, and with one vCPU (2 min for the whole stage, sigma
# 1.5 %) the candump witness of planter-can's replay lost about 28 % of the frames.
timeout --foreground -k 10 "$timeout_s" qemu-system-x86_64 -accel tcg,thread=multi -smp 2 -m 2048 \
  -nographic -no-reboot -net none -serial mon:stdio -display none -monitor none \
  -kernel "$cache/vmlinuz" -initrd "$cache/initrd.cpio.gz" \
  -append "console=ttyS0 quiet loglevel=3 panic=-1 planter_out=$run_dir planter_show=${PLANTER_VM_SHOW:-}" \
  -virtfs local,path=/,mount_tag=host,security_model=none,readonly=on,multidevs=remap \
  -virtfs "local,path=$run_dir,mount_tag=out,security_model=none" </dev/null ||
  { rc=$?; [ $rc -eq 124 ] && echo "vm-run: timed out after ${timeout_s}s" >&2; }
[ -f "$run_dir/guest-exit" ] || { echo "vm-run: the guest ended without an exit code" >&2; exit 1; }
exit "$(cat "$run_dir/guest-exit")"
