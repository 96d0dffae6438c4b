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
source "$root/tests/board_copy.sh"
expect "'can.interface'" --board "$root/boards/host-sim/board.toml"
board_copy "$root" vm-hil "$work/b1"
sed -i 's/interface = "vcan0"/interface = "nocan0"/' "$work/b1/board.toml"
expect "'can.interface': 'nocan0' does not exist" --board "$work/b1/board.toml"
board_copy "$root" vm-hil "$work/b2"
sed -i 's/priority = 80/priority = 120/' "$work/b2/board.toml"
expect "'realtime.priority'" --board "$work/b2/board.toml"
expect "no-such-file.toml" --board "$work/no-such-file.toml"
expect "--board" --record x.csv
expect "flush-ms" --board "$root/boards/vm-hil/board.toml" --flush-ms 0
board_copy "$root" rpi4-canhat "$work/b3"
sed -i 's/^id = 3$/id = 2/' "$work/b3/machines/scallion-transplanter.toml"
expect "scallion-transplanter.toml:" --board "$work/b3/board.toml"
expect "'nodes.roller_actuator.id': node ID 2 is used by another node" --board "$work/b3/board.toml"
board_copy "$root" rpi4-canhat "$work/b4"
sed -i 's/^estop_line = 22 .*/estop_line = 17/' "$work/b4/board.toml"
expect "'gpio.estop_line': line 17 is already encoder_a_line" --board "$work/b4/board.toml"
board_copy "$root" rpi4-canhat "$work/b5"
rm "$work/b5/calibration.toml"
expect "'board.calibration': $work/b5/calibration.toml: no such file" --board "$work/b5/board.toml"
exit $fail
