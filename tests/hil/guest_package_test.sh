#!/bin/sh
# Runs inside the test VM (from guest_hil_test.sh): the package as a machine gets it, and its
# service with the operator's console on the real kernel. The guest's root (the host's, over
# 9p) is read-only, so the package goes into a writable overlay of it on tmpfs: dpkg, the
# postinst (which makes the pairing secret) and /usr/bin/planterd are the package's own. Then
# what an installer does: the board file into /etc/planter, planterd started as
# planterd.service starts it (its EnvironmentFile and ExecStart, read from the installed
# unit), the commissioning check that lets its drives start, a phone's requests
# (console_client.py), and a stop by the unit's KillSignal within its TimeoutStopSec.
# Not under systemd: the VM has no systemd as PID 1 (the unit is verified by
# scripts/package-test.sh with systemd-analyze).
# Usage: guest_package_test.sh REPO BUILD DEB   (cwd: the run directory; prints "hil: ...")
set -u
R=$1
B=$2
DEB=$3
SIM=$B/apps/planter-sim/planter-sim
note() { echo "hil: $*"; }
fail=0
P=/tmp/package-root
mkdir -p /tmp/overlay/upper /tmp/overlay/work "$P"
if ! mount -t overlay overlay -o lowerdir=/,upperdir=/tmp/overlay/upper,workdir=/tmp/overlay/work "$P"; then
  note "FAIL package: no writable overlay of the guest's root (overlayfs)"
  exit 1
fi
for m in proc sys dev dev/pts; do mount --bind "/$m" "$P/$m"; done
mount -t tmpfs tmp "$P/tmp"
mount -t tmpfs run "$P/run"
mkdir -p "$P/hil" && mount --bind "$PWD" "$P/hil"
in_package_root() { chroot "$P" /bin/sh -c "$*"; }
cleanup() {
  for m in hil run tmp dev/pts dev sys proc; do umount "$P/$m" 2>/dev/null; done
  umount "$P" 2>/dev/null
}

# man-db's index is not rebuilt on this copy (its trigger runs mandb only where
# /var/lib/man-db/auto-update exists): over the host's root through 9p under TCG it took most
# of dpkg -i's 144 s. scripts/package-test.sh checks the package's man pages and installs it
# for real on the host, the trigger with it.
rm -f "$P/var/lib/man-db/auto-update"

# 1. dpkg -i, as on the machine: the postinst says the pairing secret once, for the label.
rm -f e.* e-* planter.deb
cp "$DEB" planter.deb
t0=$(date +%s)
if in_package_root "dpkg -i /hil/planter.deb" > e-install.out 2>&1; then
  note "package: dpkg -i $(basename "$DEB"): installed in $(($(date +%s) - t0)) s"
else
  note "FAIL package: dpkg -i $(basename "$DEB") failed:"; sed 's/^/    /' e-install.out
  cleanup; exit 1
fi
secret_file=$P/var/lib/planterd/pairing-secret
secret=$(head -1 "$secret_file" 2>/dev/null)
if [ -n "$secret" ] && grep -q "pairing secret is $secret" e-install.out &&
   [ "$(stat -c %a "$secret_file")" = 600 ]; then
  note "package: the installation made the pairing secret (mode 600) and said it"
else
  note "FAIL package: pairing secret '$secret' not made, not said or not mode 600"; fail=1
fi

# 2. The installer's board: this VM's (vcan0, the gpio-sim chip), with its calibration.
cp "$R/boards/vm-hil/board.toml" "$R/boards/vm-hil/calibration.toml" "$P/etc/planter/"

# 3. The service's command, as systemd runs it: the unit's EnvironmentFile, then ExecStart
# (its $PLANTERD_OPTS split on blanks, as systemd does). The package's default holds the
# drives until the commissioning stamp matches.
unit=$P/lib/systemd/system/planterd.service
env_file=$(sed -n 's/^EnvironmentFile=-\{0,1\}//p' "$unit")
exec_start=$(sed -n 's/^ExecStart=//p' "$unit")
kill_signal=$(sed -n 's/^KillSignal=SIG//p' "$unit")
stop_timeout_s=$(sed -n 's/^TimeoutStopSec=\([0-9]*\)s$/\1/p' "$unit")
if [ -z "$exec_start" ] || [ -z "$env_file" ] || [ -z "$kill_signal" ] || [ -z "$stop_timeout_s" ]; then
  note "FAIL package: the unit lacks ExecStart, EnvironmentFile, KillSignal or TimeoutStopSec"
  cleanup; exit 1
fi
note "package: starting the unit's command: $exec_start (options from $env_file)"
"$SIM" devices "$R/scenarios/hil-field-short.toml" --board "$R/boards/vm-hil/board.toml" \
  --can vcan0 --gpio planter-sim --duration 60 > e-devices.out 2> e-devices.log & DEV=$!
sleep 1
chroot "$P" /bin/sh -c "[ -r $env_file ] && . $env_file; exec $exec_start" 2> e-planterd.log & PD=$!

# 4. A phone's requests: before the check, a run is refused by the commissioning gate; then
# the check (planter-can, as the default's comment says), and the drives start.
python3 "$R/tests/hil/console_client.py" --gated e-gate-checked http://127.0.0.1:8080 \
  "$secret_file" "$P/var/lib/planterd/console-audit.log" "$P/var/lib/planterd/recording.csv" \
  > e-client.out 2>&1 & CLIENT=$!
for _ in $(seq 1 300); do [ -f e-gate-checked ] && break; sleep 0.1; done
in_package_root "planter-can --iface vcan0 --board /etc/planter/board.toml --no-progress check \
  --skip-encoder --listen-s 3 --mark-commissioned /var/lib/planterd/commissioned --json" \
  > e-check.json 2> e-check.err
rc=$?
[ $rc -eq 0 ] && note "package: planter-can check --mark-commissioned: exit 0" ||
  { note "FAIL package: planter-can check: exit $rc: $(head -3 e-check.err)"; fail=1; }
wait $CLIENT || fail=1
cat e-client.out

# 5. systemctl stop: the unit's KillSignal; planterd brings the disc to rest and exits 0 within
# the unit's TimeoutStopSec.
stop_sent=$(date +%s.%N)
kill -s "$kill_signal" $PD
waited=0
while kill -0 $PD 2>/dev/null && [ $waited -lt $((stop_timeout_s * 10)) ]; do
  sleep 0.1; waited=$((waited + 1))
done
if kill -0 $PD 2>/dev/null; then
  note "FAIL package: planterd still running ${stop_timeout_s} s after SIG$kill_signal"
  kill -9 $PD; fail=1
fi
wait $PD; rc=$?
stop_s=$(awk "BEGIN { printf \"%.2f\", $(date +%s.%N) - $stop_sent }")
[ $rc -eq 0 ] && note "package: SIG$kill_signal: planterd exit 0 in $stop_s s (limit $stop_timeout_s s)" ||
  { note "FAIL package: SIG$kill_signal: planterd exit $rc"; sed 's/^/    /' e-planterd.log; fail=1; }
kill $DEV 2>/dev/null; wait $DEV 2>/dev/null
cleanup
exit $fail
