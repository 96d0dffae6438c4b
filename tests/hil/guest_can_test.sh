#!/bin/sh
# Runs inside the test VM after the planterd runs: planter-can over the real vcan0 against
# `planter-sim devices` (scan, configure, calibrate, check, record), with an independent
# candump as the witness, then canplayer and planter-can replay the recorded log back onto
# vcan0. tests/hil/check_can.py judges the results.
# Usage: guest_can_test.sh REPO BUILD   (cwd: the run directory)
set -u
R=$1
B=$2
SIM=$B/apps/planter-sim/planter-sim
PLANTERD=$B/apps/planterd/planterd
# A copy of the board, its calibration (which the calibrations write) and the machines.
rm -rf d && mkdir d && cp "$R/boards/vm-hil/board.toml" "$R/boards/vm-hil/calibration.toml" d/ &&
  cp -r "$R/machines" d/
CAN="$B/apps/planter-can/planter-can --iface vcan0 --board d/board.toml --no-progress"
note() { echo "hil-can: $*"; }
rm -f d.candump d.candump.stop

(while [ ! -f d.candump.stop ]; do candump -L -r 8388608 vcan0 >> d.candump 2>/dev/null; sleep 0.01; done) & REC=$!
"$SIM" devices "$R/scenarios/hil-commissioning.toml" --board d/board.toml --can vcan0 \
  --gpio planter-sim --duration 95 > d-devices.out 2> d-devices.log & DEV=$!
sleep 1
$CAN --record d-session.log scan --json > d-scan.json 2> d-scan.err; echo $? > d-scan.rc
note "scan: exit $(cat d-scan.rc)"
$CAN --record d-configure.log configure > d-configure.out 2>&1; echo $? > d-configure.rc
note "configure: exit $(cat d-configure.rc)"; sed 's/^/    /' d-configure.out
# The push comes at 12 s of the devices' time: the calibration waits for it, counts, and
# ends when the wheel has been still for 2 s.
$CAN calibrate soil-wheel --distance-m 1 --ready-after-s 0 --json > d-wheel.json 2> d-wheel.err
echo $? > d-wheel.rc
note "calibrate soil-wheel: exit $(cat d-wheel.rc)"
$CAN calibrate depth --json > d-depth.json 2> d-depth.err; echo $? > d-depth.rc
note "calibrate depth: exit $(cat d-depth.rc)"
$CAN lss fastscan --json > d-lss.json 2> d-lss.err; echo $? > d-lss.rc

# planterd up with --run, held back by the commissioning gate: it boots the nodes with the
# calibrated board and runs SYNC, but starts the drives only once the check has passed.
rm -f d-stamp
"$PLANTERD" --board d/board.toml --run --commissioned-stamp d-stamp --duration 30 --log-period 0 \
  2> d-planterd.log & PD=$!
sleep 8
$CAN check --skip-encoder --listen-s 3 --mark-commissioned d-stamp --json > d-check.json \
  2> d-check.err; echo $? > d-check.rc
sleep 2  # planterd looks at the stamp once a second
note "check: exit $(cat d-check.rc)"
$CAN record d-record.log --duration 3 > d-record.out 2>&1; echo $? > d-record.rc
$CAN --record d-sdo-session.log sdo 2 r 0x1018 2 > d-sdo.out 2>&1
kill $PD 2>/dev/null; wait $PD
kill $DEV 2>/dev/null; wait $DEV
touch d.candump.stop; pkill -x candump; wait $REC

# The recorded log back onto the bus: by canplayer (can-utils) and by planter-can replay.
rm -f d-canplayer.candump d-replay.candump
candump -L -r 8388608 vcan0 > d-canplayer.candump & C=$!
sleep 0.3
canplayer -I d-record.log; echo $? > d-canplayer.rc
sleep 0.3; kill $C; wait $C 2>/dev/null
candump -L -r 8388608 vcan0 > d-replay.candump & C=$!
sleep 0.3
$CAN replay d-record.log > d-replay.out 2>&1; echo $? > d-replay.rc
sleep 0.3; kill $C; wait $C 2>/dev/null
note "canplayer: exit $(cat d-canplayer.rc), replay: exit $(cat d-replay.rc)"

/usr/bin/python3 "$R/tests/hil/check_can.py" .
