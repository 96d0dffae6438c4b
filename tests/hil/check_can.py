#!/usr/bin/env python3
"""Judges the planter-can run in the VM (tests/hil/guest_can_test.sh). Exit 1 on any failure."""
import json
import sys
from pathlib import Path

import can  # Debian's python3-can: the candump logs are read with someone else's reader

run = Path(sys.argv[1])
failures = 0


def check(name, ok, detail):
    global failures
    print(f"hil-can: {'pass' if ok else 'FAIL'} {name}: {detail}")
    failures += 0 if ok else 1


def rc(name):
    return int((run / f"d-{name}.rc").read_text().strip())


def frames(path):
    return [(m.arbitration_id, bytes(m.data)) for m in can.CanutilsLogReader(str(path))]


scan = json.loads((run / "d-scan.json").read_text())
ids = sorted(n["id"] for n in scan["nodes"] if n["answered_sdo"])
check("scan finds the board's nodes", rc("scan") == 0 and ids == [2, 3, 4, 5],
      f"nodes {ids} with profiles {[n['profile'] for n in scan['nodes']]}")
check("scan under 2 s", scan["duration_s"] < 2.0,
      f"{scan['duration_s']:.3f} s for {scan['probes']} IDs on vcan0")
configured = (run / "d-configure.out").read_text()
check("configure", rc("configure") == 0 and configured.count("stored") == 4,
      f"{configured.count('read back ok')} nodes verified and stored")

wheel = json.loads((run / "d-wheel.json").read_text())
radius = wheel["changes"][0]["after"] if rc("wheel") == 0 else float("nan")
expected = 0.150 / 0.97
check("soil-wheel calibration", abs(radius - expected) / expected < 0.01,
      f"radius {radius:.5f} m (true effective {expected:.5f} m), "
      f"{wheel['evidence']['counts']} counts, direction {wheel['evidence']['direction']}")
check("encoder direction", wheel["evidence"]["direction"] == "forward", wheel["evidence"]["direction"])
depth = json.loads((run / "d-depth.json").read_text())
top = {c["key"]: c["after"] for c in depth.get("changes", [])}.get("depth_max_mm", float("nan"))
check("depth calibration", rc("depth") == 0 and abs(top - 165.0) < 1.0,
      f"homed, travel ends at {top:.2f} mm (end stop 165 mm, board said 170 mm)")
board = (run / "d-board.toml").read_text()
check("calibrations written to the board", f"wheel_radius_m = {radius:.6g}"[:22] in board
      and "depth_max_mm" in board and (run / "d-board.toml.bak").exists(), "d-board.toml (+ .bak)")
lss = json.loads((run / "d-lss.json").read_text())
check("lss fastscan on a configured bus", rc("lss") == 0 and lss["found"] is False,
      "no unconfigured node answered, as none is there")

report = json.loads((run / "d-check.json").read_text())
bad = [i for i in report["items"] if not i["pass"]]
check("commissioning check", rc("check") == 0 and report["passed"],
      f"{len(report['items'])} items, failed: {[i['item'] + ': ' + i['detail'] for i in bad]}")

witness = frames(run / "d.candump")
session = frames(run / "d-sdo-session.log")
own = [f for f in session if 0x600 < f[0] < 0x680]
check("session log has the tool's own frames", len(own) >= 1 and all(f in witness for f in own),
      f"{len(own)} SDO requests sent by planter-can, all seen by candump")
recorded = frames(run / "d-record.log")
check("record", rc("record") == 0 and len(recorded) > 500, f"{len(recorded)} frames in 3 s")
played = frames(run / "d-canplayer.candump")
check("canplayer replays planter-can's log", rc("canplayer") == 0 and played == recorded,
      f"{len(played)} of {len(recorded)} frames, same IDs and bytes in order")
replayed = frames(run / "d-replay.candump")
check("planter-can replay", rc("replay") == 0 and replayed == recorded,
      f"{len(replayed)} of {len(recorded)} frames, same IDs and bytes in order")
sys.exit(1 if failures else 0)
