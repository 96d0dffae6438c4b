#!/usr/bin/env bash
# The candump logs planter-can writes are read back by other people's readers: python-can's
# CanutilsLogReader and can-utils' log2long (the parser canplayer uses). Both must see every
# frame, with the same IDs, lengths and bytes. (canplayer itself replays one onto vcan0 in
# the VM test.)
set -euo pipefail
tool=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$tool" --iface sim --board "$src/boards/host-sim/board.toml" --sim-controller --no-progress \
  record "$work/bus.log" --duration 2 >/dev/null
lines=$(grep -c '^(' "$work/bus.log")
[ "$lines" -gt 100 ] || { echo "only $lines frames recorded"; exit 1; }

# can-utils: one line out per frame in, no complaints.
log2long <"$work/bus.log" >"$work/long.txt"
[ "$(wc -l <"$work/long.txt")" -eq "$lines" ] || { echo "log2long read $(wc -l <"$work/long.txt") of $lines"; exit 1; }

# python-can (Debian's python3-can, so Debian's python3).
/usr/bin/python3 - "$work/bus.log" <<'PY'
import sys
import can
path = sys.argv[1]
msgs = list(can.CanutilsLogReader(path))
lines = [l.split() for l in open(path) if l.startswith('(')]
assert len(msgs) == len(lines), f"python-can read {len(msgs)} of {len(lines)} frames"
for m, (stamp, iface, frame) in zip(msgs, lines):
    ident, data = frame.split('#')
    assert m.arbitration_id == int(ident, 16), (m, frame)
    assert bytes(m.data) == bytes.fromhex(data), (m, frame)
    assert abs(m.timestamp - float(stamp.strip('()'))) < 1e-6, (m, stamp)
    assert m.channel == iface, (m.channel, iface)
print(f"python-can and log2long read all {len(msgs)} frames")
PY
