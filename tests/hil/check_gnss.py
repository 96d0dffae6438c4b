#!/usr/bin/env python3
"""Judges guest_gnss_test.sh's run on the VM: planterd reading the simulator's NMEA log through
gpsfake and a real gpsd. The fixes used, the alarm within 1 s of the last fix before the log
ends, the soil wheel alone while it is out, the recovery when gpsd is back, the antenna's place
in the recording and the as-planted map. Prints every figure, exits 1 on a failed check.
Usage: check_gnss.py RUN_DIR"""
import csv
import json
import math
import os
import re
import sys

run = sys.argv[1]
LOST = 1 << 10  # warning bit 10 (firmware/supervisor/supervisor.h)
HOLD_S = 2.0  # LoopAlarmConfig::hold_s
failed = []


def check(ok, what):
    print(("hil: gnss: " if ok else "hil: FAIL gnss: ") + what)
    if not ok:
        failed.append(what)


def read(name):
    return open(os.path.join(run, name)).read()


rc = read("g-planterd.rc").strip()
log = read("g-planterd.log")
check(rc == "0", f"planterd exit {rc}")
rows = list(csv.DictReader(l for l in open(os.path.join(run, "g.csv")) if not l.startswith("#")))
t = [float(r["t"]) for r in rows]
lost = [int(r["warnings"]) & LOST != 0 for r in rows]
lat = [float(r["lat_deg"]) for r in rows]
placed = [v != 0.0 for v in lat]  # a fix no older than a second (docs/recording-format.md)
# Where the fix arrived: the row where the place changed.
arrivals = [i for i in range(1, len(rows)) if placed[i] and lat[i] != lat[i - 1]]
check(len(arrivals) >= 100, f"{len(arrivals)} fixes through gpsd used in the run")
# The sky blocked mid-row: the first stretch of rows with no place after fixes came.
gap = next((i for i in range(1, len(rows)) if placed[i - 1] and not placed[i]), None)
if gap is None:
    check(False, "the fix was never lost")
    sys.exit(1)
back = next((i for i in range(gap, len(rows)) if placed[i]), None)
last_fix = t[max(a for a in arrivals if a < gap)]
alarm = next((t[i] for i in range(gap, len(rows)) if lost[i]), None)
print(f"hil: gnss: fix lost after {last_fix:.2f} s, back at "
      f"{'never' if back is None else '%.2f s' % t[back]}")
check(alarm is not None and alarm - last_fix <= 1.0,
      f"fix lost: alarm 'no GNSS fix' at {alarm} s, {(alarm or 0) - last_fix:.2f} s after the last "
      "fix (goal: within 1 s)")
steady = [lost[i] for i in range(len(rows)) if last_fix - 5.0 <= t[i] <= last_fix]
check(steady and not any(steady), "no alarm in the 5 s before the fix was lost")
check(back is not None, "the fix came back (8 s of sky blocked in the log)")
if back is not None:
    out = [lost[i] for i in range(len(rows)) if alarm is not None and alarm < t[i] < t[back]]
    check(out and all(out), "the alarm held while no fix came (the soil wheel alone)")
    # An alarm stays up hold_s (2 s) after its condition clears, so a glance catches it
    # (firmware/supervisor/loop_alarms.h); the fix is in use again at once.
    cleared = next((t[i] for i in range(back, len(rows)) if not lost[i]), None)
    check(cleared is not None and cleared - t[back] <= HOLD_S + 0.5,
          f"the alarm cleared at {cleared} s, the fix back at {t[back]:.2f} s "
          f"(the alarm's hold {HOLD_S} s)")
# gpsd stopped (gpsfake killed), on the wall clock from planterd's launch (its rows' time starts
# a moment later, so the figure can read early by that moment, never late).
gone = float(read("g-gpsd-kill-wall")) - float(read("g-start-wall"))
late = next((t[i] for i in range(len(rows)) if t[i] > gone - 1.0 and lost[i]), None)
check(late is not None and late - gone <= 1.0,
      f"gpsd stopped at about {gone:.2f} s: alarm at {late} s (goal: within 1 s)")
placed_lat = [v for v in lat if v != 0.0]
check(placed_lat and all(36.69 < v < 36.71 for v in placed_lat),
      f"the antenna's place in the recording: {len(placed_lat)} rows at latitude "
      f"{min(placed_lat, default=0):.6f}..{max(placed_lat, default=0):.6f}")
for name in ("raised", "cleared"):
    check(f"planterd: alarm {name}: no GNSS fix" in log, f"planterd's log: alarm {name}: no GNSS fix")
m = re.search(r"as planted: (\d+) seedlings placed by GNSS, (\d+) seen with no fix", log)
check(m is not None, "planterd said how many seedlings it placed")
geo = json.loads(read("g.as_planted.geojson"))
points = [f for f in geo["features"] if f["geometry"]["type"] == "Point"]
track = [f for f in geo["features"] if f["geometry"]["type"] == "LineString"][0]["geometry"]["coordinates"]
if m:
    n_placed, unplaced = int(m.group(1)), int(m.group(2))
    check(n_placed > 0 and len(points) == n_placed and unplaced > 0,
          f"as planted: {n_placed} seedlings placed, {len(points)} points in the map, "
          f"{unplaced} seen while the fix was out")
lon0, lat0 = track[0]
far = max((math.hypot((p["geometry"]["coordinates"][0] - lon0) * 111320 * math.cos(math.radians(lat0)),
                      (p["geometry"]["coordinates"][1] - lat0) * 110540) for p in points), default=0)
check(len(track) >= 100 and far < 20.0,
      f"the map: a track of {len(track)} fixes, seedlings within {far:.1f} m of its start")
sys.exit(1 if failed else 0)
