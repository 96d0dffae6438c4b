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
# Issue 28, item 14: NaN passed every range check of the command lines.
expect 2 "'nan' is not a finite number" -- --board "$board" --iface sim replay "$work/none.log" --max-gap nan
expect 2 "'inf' is not a finite number" -- --board "$board" --iface sim monitor --duration inf
# Issue 28, item 13: a type that does not fit the object is said, never printed as its low byte.
expect 1 "the object holds 4 bytes, not the 1 of this type: read it as a 32-bit type" -- --iface sim --board "$board" sdo 2 r 0x1018 2 u8
expect 1 "the object holds 4 bytes, not the 2 of this type" -- --iface sim --board "$board" sdo 2 r 0x1018 2 u16
expect 0 "^0x00402001$" -- --iface sim --board "$board" sdo 2 r 0x1018 2 x32
# On sim with no board the host-sim board is taken, and the tool says so.
expect 0 "the host-sim board (.*boards/host-sim/board.toml)" -- --iface sim scan
expect 0 "4 node(s) on sim" -- --iface sim scan
# An index typed as tables print it, without 0x, is decimal in CiA 309-3: the error says so.
expect 1 "the index 1018 was read as decimal (0x03FA): write 0x1018" -- --iface sim --board "$board" sdo 2 r 1018 1
expect 2 "is not an NMT command" -- --iface sim --board "$board" nmt begin 2
expect 2 "is not a node-ID" -- --iface sim --board "$board" info plough
expect 2 "--iface is required" -- --board "$board" scan
expect 2 "nosuch0" -- --iface nosuch0 scan
expect 2 "missing.txt: no such file" -- --iface sim --board "$board" sdo -f "$work/missing.txt"
expect 2 "missing.log: no such file" -- --board "$board" decode "$work/missing.log"
printf '(9.000000) can0 702#05\n(8.999000) can0 702#05\n(2.500000) can0 702#05\n' >"$work/backwards.log"
expect 2 "backwards.log:3: time goes back by more than 1 s" -- --board "$board" decode "$work/backwards.log"
printf '(1.000000) can0 702#05\n(2.000000) can0 7020#05\n' >"$work/badid.log"
expect 2 "badid.log:2: frame ID '7020' is not 3 or 8 hex digits" -- --iface sim --board "$board" replay "$work/badid.log"
# A log's bytes never reach the terminal raw (issue 53, item 12): ESC and OSC shown as '?'.
printf '(1.000000) can0 702#05\n(2.000000) can0 7\033]0;x\007#05\n' >"$work/escid.log"
printf '(1.0\033[2J) can0 702#05\n' >"$work/escts.log"
for cmd in replay decode; do
  for log in escid escts; do
    out=$(timeout 20 "$tool" --no-progress --iface sim --board "$board" $cmd "$work/$log.log" 2>&1 </dev/null)
    if [ $? -ne 2 ] || printf '%s' "$out" | grep -q "$(printf '\033')" || ! grep -q "$log.log:[12]: .*'.*?.*'" <<<"$out"; then
      echo "FAIL: planter-can $cmd $log.log echoed control bytes or no line: $(printf '%s' "$out" | od -c | head -3)"
      fails=$((fails + 1))
    fi
  done
done
printf '[can]\nbitrate = 5\n' >"$work/bad.toml"
expect 2 "bad.toml" -- --iface sim --board "$work/bad.toml" scan
expect 2 "is not a calibration" -- --iface sim --board "$board" calibrate weight
expect 2 "out of range 1-127" -- --iface sim --board "$board" lss assign 200
# Node 2 (the disc drive) is on the bus: a second node with ID 2 is refused.
expect 1 "node-ID 2 is already used by a node on the bus" -- --iface sim --board "$board" lss assign 2
expect 0 "unconfigured -> 9, stored, boot-up seen" -- --iface sim --board "$board" lss assign 9
expect 0 "4 node(s) on sim" -- --iface sim --board "$board" scan
expect 1 "FAIL  SYNC rate" -- --iface sim --no-sim-controller --board "$board" check --skip-encoder
# The README's commissioning session on sim, as written: the controller has booted the nodes
# before the tool speaks, and a healthy machine passes every item.
expect 0 "all 26 items passed" -- --iface sim --board "$src/boards/host-sim/board.toml" --sim-controller check

# Inputs that are not files, or hold no frames, are refused (exit 2), never blocked on or
# reported as "0 of 0 frames replayed".
mkfifo "$work/fifo.log" "$work/fifo.txt"
expect 2 "fifo.txt: is a FIFO, not a regular file" -- --iface sim --board "$board" sdo -f "$work/fifo.txt"
expect 2 "fifo.log: is a FIFO, not a regular file" -- --iface sim --board "$board" replay "$work/fifo.log"
mkdir "$work/dir.log"
expect 2 "dir.log: is a directory, not a file" -- --iface sim --board "$board" replay "$work/dir.log"
: >"$work/empty.log"
expect 2 "empty.log: no frame lines" -- --iface sim --board "$board" replay "$work/empty.log"
head -c 4096 /dev/urandom | tr -d '(' >"$work/garbage.log"
expect 2 "garbage.log: no frame lines" -- --iface sim --board "$board" replay "$work/garbage.log"
# Windows files: a UTF-8 byte-order mark does not hide the first frame or the first command.
printf '\xef\xbb\xbf(1.000000) can0 702#05\n(1.100000) can0 702#05\n' >"$work/bom.log"
expect 0 "2 of 2 frames replayed" -- --iface sim --board "$board" replay "$work/bom.log"
printf '\xef\xbb\xbf2 r 0x1000 0 u32\r\n' >"$work/bom.txt"
expect 0 "^402$" -- --iface sim --board "$board" sdo -f "$work/bom.txt"
# A log cut mid-line (a recorder killed while writing): the whole frames are used, the cut line
# is said and skipped; a bad line that ends in a newline is still refused.
printf '(1.000000) can0 702#05\n(1.100000) can0 702#05\n(1.2000' >"$work/cut.log"
expect 0 "2 of 2 frames replayed" -- --iface sim --board "$board" replay "$work/cut.log"
expect 0 "cut.log:3: the last line is cut" -- --iface sim --board "$board" replay "$work/cut.log"
# A silence of 11 days in a log is shortened (and said), not replayed for hours.
printf '(1.000000) can0 702#05\n(1000001.000000) can0 702#05\n' >"$work/gap.log"
expect 0 "1 silence(s) longer than 10 s shortened" -- --iface sim --board "$board" replay "$work/gap.log"
# Open-ended monitor/record on simulated time would never end: refused.
expect 2 "give --duration S" -- --iface sim --board "$board" monitor --duration 0
expect 2 "give --duration S" -- --iface sim --board "$board" record "$work/r.log"
# An NMT command nobody confirms is a timeout (exit 1), as the README says.
expect 1 "not confirmed" -- --iface sim --board "$board" nmt start 100
# decode -o: a bad log leaves the existing CSV as it was; an unwritable -o exits 1.
echo "keep" >"$work/existing.csv"
expect 2 "backwards.log:3" -- --board "$board" decode "$work/backwards.log" -o "$work/existing.csv"
[ "$(cat "$work/existing.csv")" = keep ] || { echo "FAIL: decode -o changed existing.csv"; fails=$((fails + 1)); }
printf '(1.000000) can0 080#\n(1.010000) can0 080#\n' >"$work/sync.log"
mkdir "$work/outdir"
expect 1 "outdir: is a directory" -- --board "$board" decode "$work/sync.log" -o "$work/outdir"
# The session log (--record) on a full disk: exit 1 naming it, not a silent empty log. A file
# size limit of 1 kB stands for the full disk (SIGXFSZ ignored: the write fails with EFBIG).
out=$(trap '' XFSZ; ulimit -f 1; timeout 20 "$tool" --no-progress --iface sim --board "$board" \
  --record "$work/full.log" scan 2>&1 </dev/null)
rc=$?
if [ $rc -ne 1 ] || ! grep -q -- "--record: $work/full.log: cannot be written (disk full?)" <<<"$out"; then
  echo "FAIL: --record on a full disk -> exit $rc, output:"; echo "$out" | sed 's/^/    /'
  fails=$((fails + 1))
fi
# Issue 28, item 11: a log that exists is never truncated: refused, and left as it was.
printf 'a log of yesterday\n' >"$work/old.log"
expect 2 "--record: $work/old.log: exists: a log is never overwritten" -- --iface sim --board "$board" --record "$work/old.log" scan
expect 2 "record: $work/old.log: exists: a log is never overwritten" -- --iface sim --board "$board" record "$work/old.log" --duration 1
grep -q "a log of yesterday" "$work/old.log" || { echo "FAIL: the old log was changed"; fails=$((fails + 1)); }
# A board whose TPDO maps an object the node does not have: configure names the step and the
# abort (the controller's boot runs the same script, so it faults with boot error J).
source "$src/tests/board_copy.sh"
board_copy "$src" host-sim "$work/badmap"
sed -i 's|tpdo2 = \["6064:00:32", "6077:00:16"\]|tpdo2 = ["6064:00:32", "2077:00:16"]|' \
  "$work/badmap/machines/scallion-transplanter.toml"
expect 1 "2 r 0x2077 0 u16): abort 0x06020000" -- --iface sim --board "$work/badmap/board.toml" configure
# Issue 29: calibrating the simulated machine as the README shows it rewrote the project's
# board files. On sim the result is shown and nothing is written unless --write-sim is given.
board_copy "$src" host-sim "$work/cal"
before=$(md5sum "$work/cal/calibration.toml" "$work/cal/board.toml")
expect 0 "not written into $work/cal/board.toml (give --write-sim" -- --iface sim --board "$work/cal/board.toml" calibrate force --known-N 50 --ready-after-s 0
[ "$before" = "$(md5sum "$work/cal/calibration.toml" "$work/cal/board.toml")" ] && ! ls "$work/cal"/*.bak* >/dev/null 2>&1 ||
  { echo "FAIL: calibrate on sim changed the board's files"; fails=$((fails + 1)); }
expect 0 "written to $work/cal/calibration.toml" -- --iface sim --board "$work/cal/board.toml" calibrate force --known-N 50 --ready-after-s 0 --write-sim
# Issue 29: the commands of docs/planter-can.md, in its order, on sim as a newcomer types them
# (no --board, no --sim-controller): each works, and the project's files stay as they were.
tracked=$(cd "$src" && git status --porcelain -- boards machines 2>/dev/null | md5sum)
expect 0 "4 node(s) on sim" -- --iface sim scan
expect 0 "TPDO1" -- --iface sim info 2
expect 0 "4202497" -- --iface sim sdo 2 r 0x1018 2 u32
expect 0 "stop node 2: confirmed" -- --iface sim nmt stop 2
expect 0 "start all nodes: confirmed, heartbeat says operational (nodes 2 3 4 5)" -- --iface sim nmt start all
expect 1 "from node(s) 2 3 4 5" -- --iface sim --no-sim-controller nmt start all
expect 0 "read back ok, stored" -- --iface sim configure
expect 0 "not written" -- --iface sim calibrate force --known-N 50 --ready-after-s 0
expect 0 "not written" -- --iface sim calibrate soil-wheel --distance-m 2 --ready-after-s 0
expect 0 "control.depth_max_mm .* 165 " -- --iface sim calibrate depth --ready-after-s 0
expect 2 "planterd must be stopped" -- --iface sim --sim-controller calibrate depth
expect 0 "all 26 items passed" -- --iface sim check
expect 0 "frames, bus load" -- --iface sim monitor --duration 1
[ "$tracked" = "$(cd "$src" && git status --porcelain -- boards machines 2>/dev/null | md5sum)" ] ||
  { echo "FAIL: the documented commands on sim changed the project's boards or machines"; fails=$((fails + 1)); }
[ "$fails" -eq 0 ] && echo "planter-can command line: all cases behave"
exit "$fails"
