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


def load(name):
    """A command's JSON output; {} when it printed none (its exit code says why)."""
    try:
        return json.loads((run / f"d-{name}.json").read_text())
    except (OSError, ValueError):
        return {}


def frames(path):
    return [(m.arbitration_id, bytes(m.data)) for m in can.CanutilsLogReader(str(path))]


scan = load("scan")
nodes = scan.get("nodes", [])
ids = sorted(n["id"] for n in nodes if n["answered_sdo"])
check("scan finds the board's nodes", rc("scan") == 0 and ids == [2, 3, 4, 5],
      f"nodes {ids} with profiles {[n['profile'] for n in nodes]}")
check("scan under 2 s", scan.get("duration_s", 99) < 2.0,
      f"{scan.get('duration_s', float('nan')):.3f} s for {scan.get('probes')} IDs on vcan0")
configured = (run / "d-configure.out").read_text()
check("configure", rc("configure") == 0 and configured.count("stored") == 4,
      f"{configured.count('read back ok')} nodes verified and stored")

wheel = load("wheel")
radius = wheel["changes"][0]["after"] if rc("wheel") == 0 and wheel else float("nan")
evidence = wheel.get("evidence", {})
expected = 0.150 / 0.97
check("soil-wheel calibration", abs(radius - expected) / expected < 0.01,
      f"radius {radius:.5f} m (true effective {expected:.5f} m), {evidence.get('counts')} counts, "
      f"{evidence.get('invalid_transitions')} invalid A/B transitions"
      + ("" if rc("wheel") == 0 else "; " + (run / "d-wheel.err").read_text().strip().splitlines()[-1]))
check("encoder direction", evidence.get("direction") == "forward", str(evidence.get("direction")))
depth = load("depth")
top = {c["key"]: c["after"] for c in depth.get("changes", [])}.get("depth_max_mm", float("nan"))
check("depth calibration", rc("depth") == 0 and abs(top - 165.0) < 1.0,
      f"homed, travel ends at {top:.2f} mm (end stop 165 mm)")
calibration = (run / "d" / "calibration.toml").read_text()
check("calibrations written to the unit's calibration file",
      f"wheel_radius_m = {radius:.6g}"[:22] in calibration and "depth_max_mm" in calibration
      and (run / "d" / "calibration.toml.bak").exists(), "d/calibration.toml (+ .bak)")
lss = load("lss")
check("lss fastscan on a configured bus", rc("lss") == 0 and lss.get("found") is False,
      "no unconfigured node answered, as none is there")

report = load("check")
items = report.get("items", [])
bad = [i for i in items if not i["pass"]]
check("commissioning check", rc("check") == 0 and report.get("passed") is True,
      f"{len(items)} items, failed: {[i['item'] + ': ' + i['detail'] for i in bad]}")

log = (run / "d-planterd.log").read_text()
held = "drives stay off: no commissioning stamp" in log
released = "matches the board" in log and "ready -> running" in log
check("drives held until commissioned", held and released and
      log.index("drives stay off") < log.index("ready -> running"),
      "planterd --run waited in ready for the stamp, then started the drives"
      if held and released else f"log: {log[-400:]}")

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
