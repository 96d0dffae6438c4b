#!/usr/bin/python3
"""planter-fit explains a recording the operator makes from the console (issue 32, item 2).

`planter-sim live` runs the field scenario in real time (here four simulated seconds a second);
the operator logs in with the pairing secret, waits for the opener to reach its working depth,
starts a recording with the console's own command, lets it run for about 28 simulated seconds and stops it; planter-fit on that recording,
nothing hidden, must say "no significant mismatch" on all six channels. (A 28 s console
recording once got a transport delay of 11.7 ms on omega: one SYNC period, which the recording
now declares.)
Usage: fit_explains_a_console_recording_test.py PLANTER_SIM PLANTER_FIT SOURCE_DIR
"""
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sim, fit, src = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tests"))
from live_console import console_address, http_call  # noqa: E402

SPEED = 4.0        # simulated seconds a wall-clock second
RECORD_S = 28.0    # simulated seconds recorded

work = tempfile.mkdtemp()
log_path = os.path.join(work, "live.log")
log = open(log_path, "w")
live = subprocess.Popen([sim, "live", os.path.join(src, "scenarios/zhangqiu-field.toml"),
                         "--port", "0", "--dir", os.path.join(work, "live"),
                         "--speed", str(SPEED)], stdout=log, stderr=subprocess.STDOUT)


def fail(what):
    print("FAIL " + what)
    live.kill()
    live.wait()
    shutil.rmtree(work, ignore_errors=True)
    sys.exit(1)


try:
    url, secret = console_address(log_path)

    def call(path, body=None, headers=None):
        return http_call(url, path, body, headers)

    status, body, headers = call("/api/login", {"secret": secret})
    if status != 200:
        fail("the operator's login: %d %s" % (status, body))
    auth = {"Cookie": headers.get("Set-Cookie", "").split(";")[0],
            "X-CSRF-Token": json.loads(body).get("csrf", "")}
    # The operator records the work: once the machine runs with the opener down at its
    # working depth. A recording that holds the opener's lowering is not clean (issue 52, in
    # docs/planter-fit.md): the lowering runs at the drive's profile velocity, 20 mm/s, which
    # the depth channel's rate limit, started at 50 mm/s, never reaches, so the ramp's lag goes
    # into T_a; held-out RMS 0.010 mm for a noise of 0.001 mm, and two runs in three named a
    # vibration or a delay of it.
    # The machine waits for Start (issue 54): the operator presses it once it is ready.
    for _ in range(150):
        status, body, _ = call("/api/command", {"command": "run"}, auth)
        if status == 200:
            break
        time.sleep(0.2)
    else:
        fail("Start planting was never accepted: %d %s" % (status, body))
    state = None
    for _ in range(150):
        status, body, _ = call("/api/state", headers=auth)
        now = json.loads(body) if status == 200 else {}
        state = now.get("state")
        depth, target = now.get("depth_mm"), now.get("depth_target_mm")
        if state == "running" and depth is not None and target is not None \
                and abs(depth - target) < 1.0:
            break
        time.sleep(0.2)
    else:
        fail("the machine never ran with the opener down: %s" % state)
    status, body, _ = call("/api/command", {"command": "record_start"}, auth)
    if status != 200 or "recording to" not in body:
        fail("record_start: %d %s" % (status, body))
    time.sleep(RECORD_S / SPEED)
    status, body, _ = call("/api/command", {"command": "record_stop"}, auth)
    if status != 200 or "closed" not in body:
        fail("record_stop: %d %s" % (status, body))
finally:
    live.terminate()
    live.wait()

recordings = glob.glob(os.path.join(work, "live", "recordings", "*.csv"))
if len(recordings) != 1:
    fail("one recording expected, found %s" % recordings)
out = subprocess.run([fit, recordings[0], "--out", os.path.join(work, "fit"), "--jobs", "2"],
                     capture_output=True, text=True)
print(out.stdout, end="")
if out.returncode != 0:
    fail("planter-fit exited %d: %s" % (out.returncode, out.stderr))
m = re.search(r"^recording: .*, ([0-9.]+) s \(held out", out.stdout, re.M)
seconds = float(m.group(1)) if m else 0.0
if seconds < 0.8 * RECORD_S:
    fail("the recording holds %.1f s, asked for about %.0f" % (seconds, RECORD_S))
channels = re.findall(r"^(?:ground|disc drive|clamp|depth) .*$", out.stdout, re.M)
clean = [c for c in channels if " no significant mismatch " in c]
if len(channels) != 6 or len(clean) != 6:
    fail("%d of %d channels are 'no significant mismatch' on the console's recording"
         % (len(clean), len(channels)))
shutil.rmtree(work, ignore_errors=True)
print("PASS: the console's %.1f s recording, 6 of 6 channels clean" % seconds)
