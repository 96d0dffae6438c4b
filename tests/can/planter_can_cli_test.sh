#!/usr/bin/env bash
# planter-can from the command line: every bad input gets one clear line and exit code 2; a
# node that never answers gives a timeout message and exit 1, not a hang.
set -uo pipefail
tool=$1
src=$2
board="$src/boards/host-sim/board.toml"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
expect() {  # expect CODE PATTERN -- ARGS...
  local code=$1 pattern=$2
  shift 3
  local out rc
  out=$(timeout 20 "$tool" --no-progress "$@" 2>&1 </dev/null)
  rc=$?
  if [ "$rc" -ne "$code" ] || ! grep -q -- "$pattern" <<<"$out"; then
    echo "FAIL: planter-can $* -> exit $rc (want $code), output:"
    echo "$out" | sed 's/^/    /'
    fails=$((fails + 1))
  fi
}
expect 2 "token 3 '0x1g00'" -- --iface sim --board "$board" sdo 2 r 0x1g00 0
expect 2 "token 2 'rd'" -- --iface sim --board "$board" sdo 2 rd 0x1000 0
expect 2 "token 6 'abc'" -- --iface sim --board "$board" sdo 2 w 0x1017 0 u16 abc
expect 1 "no answer from node 77 in 100 ms" -- --iface sim --board "$board" sdo 77 r 0x1000 0
expect 2 "is not an NMT command" -- --iface sim --board "$board" nmt begin 2
expect 2 "is not a node-ID" -- --iface sim --board "$board" info plough
expect 2 "--iface is required" -- --board "$board" scan
expect 2 "needs --board or --sim-scenario" -- --iface sim scan
expect 2 "nosuch0" -- --iface nosuch0 scan
expect 2 "cannot be read" -- --iface sim --board "$board" sdo -f "$work/missing.txt"
expect 2 "cannot be read" -- --board "$board" decode "$work/missing.log"
printf '(9.000000) can0 702#05\n(8.999000) can0 702#05\n(2.500000) can0 702#05\n' >"$work/backwards.log"
expect 2 "backwards.log:3: time goes back by more than 1 s" -- --board "$board" decode "$work/backwards.log"
printf '(1.000000) can0 702#05\n(2.000000) can0 7020#05\n' >"$work/badid.log"
expect 2 "badid.log:2: frame ID '7020' is not 3 or 8 hex digits" -- --iface sim --board "$board" replay "$work/badid.log"
printf '[can]\nbitrate = 5\n' >"$work/bad.toml"
expect 2 "bad.toml" -- --iface sim --board "$work/bad.toml" scan
expect 2 "is not a calibration" -- --iface sim --board "$board" calibrate weight
expect 2 "out of range 1-127" -- --iface sim --board "$board" lss assign 200
expect 0 "4 node(s) on sim" -- --iface sim --board "$board" scan
expect 1 "FAIL  SYNC rate" -- --iface sim --board "$board" check --skip-encoder
[ "$fails" -eq 0 ] && echo "planter-can command line: all cases behave"
exit "$fails"
