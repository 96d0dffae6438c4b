#!/bin/sh
# Runs inside the test VM (tests/hil/guest_hil_test.sh): GNSS on the real kernel. The
# simulator's run of scenarios/hil-gnss.toml writes its receiver's NMEA log, with the sky
# blocked for 8 s mid-row; gpsfake (Debian's gpsd-clients) plays it to a real gpsd. Once gpsd
# gives fixes, planterd, on a board that reads gpsd, drives `planter-sim devices`; 40 s in,
# gpsfake is stopped and gpsd goes with it. check_gnss.py judges: the fixes used, the alarm
# within 1 s of the fix lost, the wheel alone, the recovery, the alarm when gpsd stops, the
# place in the recording and the as-planted map.
# Usage: guest_gnss_test.sh REPO BUILD   (cwd: the run directory)
set -u
R=$1
B=$2
PLANTERD=$B/apps/planterd/planterd
SIM=$B/apps/planter-sim/planter-sim
CAN=$B/apps/planter-can/planter-can
note() { echo "hil: $*"; }
command -v gpsfake >/dev/null || { note "FAIL gnss: gpsfake is not installed (gpsd-clients)"; exit 1; }
rm -rf g-* g.*
"$SIM" run "$R/scenarios/hil-gnss.toml" --out g-sim --quiet > g-sim.log 2>&1 ||
  { note "FAIL gnss: planter-sim run"; cat g-sim.log; exit 1; }
port=2950
{ cat "$R/boards/vm-hil/board.toml"
  printf '\n[gnss]\nreceiver = "gpsd"\ngpsd_port = %d\nantenna_ahead_m = 0.4\n' "$port"; } > g-board.toml
# Sentences 50 ms apart: RMC and GGA of a 10 Hz receiver. -n: gpsd reads the log at once; under
# emulation gpsfake and gpsd take tens of seconds to start, so planterd starts once fixes flow.
date +%s.%N > g-gpsfake-wall
gpsfake -q -n -1 -W 300 -P "$port" -c 0.05 g-sim/gnss.nmea > g-gpsfake.log 2>&1 & GF=$!
n=0
until "$CAN" gnss --port "$port" --duration 1 > g-watch.log 2>&1 &&
      grep -q "fixes, [1-9][0-9]* usable" g-watch.log; do
  n=$((n + 1))
  [ $n -ge 60 ] && { note "FAIL gnss: no usable fix from gpsd in 60 tries"; kill $GF; exit 1; }
done
# The log's time now (its fixes' UTC, from 08:00:00): planterd starts at its 25th second, so
# the sky blocked at about 45 s falls 20 s into planterd's run.
log_s=$(awk '/ UTC /{ split($3, a, ":"); t = (a[1] - 8) * 3600 + a[2] * 60 + a[3] } END { print t + 0 }' g-watch.log)
wait_s=$(awk -v t="$log_s" 'BEGIN { w = 24 - t; print (w > 0 ? w : 0) }')
note "gnss: gpsd gives fixes $(awk -v a="$(cat g-gpsfake-wall)" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }') s after gpsfake started; the log at ${log_s} s"
sleep "$wait_s"
"$SIM" devices "$R/scenarios/hil-gnss.toml" --board g-board.toml --can vcan0 --gpio planter-sim \
  --duration 48 > g-devices.out 2> g-devices.log & DEV=$!
sleep 1
date +%s.%N > g-start-wall
"$PLANTERD" --board g-board.toml --record g.csv --run --duration 45 --log-period 5 \
  2> g-planterd.log & PD=$!
sleep 40
date +%s.%N > g-gpsd-kill-wall
kill $GF; wait $GF
wait $PD; echo $? > g-planterd.rc
wait $DEV
python3 "$R/tests/hil/check_gnss.py" . || exit 1
