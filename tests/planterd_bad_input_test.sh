#!/usr/bin/env bash
# planterd on bad input, on any machine: one message naming the file and key, exit code 2,
# never a hang. (The same for real interfaces and chips runs in the VM test.)
set -uo pipefail
planterd=$1
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
expect() {  # expected-substring, args...
  local want=$1
  shift
  timeout 10 "$planterd" "$@" > "$work/out" 2> "$work/err"
  local rc=$?
  if [ $rc -ne 2 ] || ! grep -qF -- "$want" "$work/err" || [ "$(wc -l < "$work/err")" -ne 1 ]; then
    echo "FAIL planterd $*: exit $rc, stderr: $(cat "$work/err")"
    fail=1
  else
    echo "ok   planterd $*: $(cat "$work/err")"
  fi
}
expect "'can.interface'" --board "$root/boards/host-sim/board.toml"
sed 's/interface = "vcan0"/interface = "nocan0"/' "$root/boards/vm-hil/board.toml" > "$work/b1.toml"
expect "'can.interface': 'nocan0' does not exist" --board "$work/b1.toml"
sed 's/priority = 80/priority = 120/' "$root/boards/vm-hil/board.toml" > "$work/b2.toml"
expect "'realtime.priority'" --board "$work/b2.toml"
expect "no-such-file.toml" --board "$work/no-such-file.toml"
expect "--board" --record x.csv
expect "flush-ms" --board "$root/boards/vm-hil/board.toml" --flush-ms 0
sed 's/^id = 3$/id = 2/' "$root/boards/rpi4-canhat/board.toml" > "$work/b3.toml"
expect "'nodes.roller_actuator.id': node ID 2 is used by another node" --board "$work/b3.toml"
sed 's/^estop_line = 22 .*/estop_line = 17/' "$root/boards/rpi4-canhat/board.toml" > "$work/b4.toml"
expect "'gpio.estop_line': line 17 is already encoder_a_line" --board "$work/b4.toml"
exit $fail
