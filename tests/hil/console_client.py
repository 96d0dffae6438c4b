#!/usr/bin/python3
"""planterd's console on the real kernel (in the test VM), as a phone on the machine's network
would use it: the page and the live values open to view; a command without a session gets
401; the operator logs in with the pairing secret, starts a recording, sets the depth (which
planterd's recording then holds), is told a depth out of range is refused, and stops the
recording, which holds the new target and downloads whole; wrong secrets are limited; the
audit log has it all; the recordings are offered for download. Prints one line per check ("hil: ...").
With --gated FILE (the installed package, not yet commissioned): first an operator's run is
refused by the commissioning gate, then FILE is made and the machine awaited until it runs.
Usage: console_client.py [--gated FILE] URL SECRET_FILE AUDIT_LOG RECORDING   (exits 1 on any failure)
"""
import json, os, sys, time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from live_console import http_call  # noqa: E402

args = sys.argv[1:]
gated = None
if args[:1] == ["--gated"]:
    gated, args = args[1], args[2:]
url, secret_file, audit_path, recording = args[:4]
secret = open(secret_file).read().split("\n")[0]
fail = 0


def say(ok, what):
    global fail
    print("hil: %s%s" % ("" if ok else "FAIL ", what))
    fail |= 0 if ok else 1


def call(path, body=None, headers=None):
    return http_call(url, path, body, headers)


def log_in():
    status, body, headers = call("/api/login", {"secret": secret})
    cookie = headers.get("Set-Cookie", "").split(";")[0]
    csrf = json.loads(body).get("csrf", "") if status == 200 else ""
    return status, {"Cookie": cookie, "X-CSRF-Token": csrf}


if gated:
    # Not commissioned: the console is up, the drives are held, and a run is refused.
    status = None
    for _ in range(150):
        try:
            status, auth = log_in()
            break
        except OSError:
            time.sleep(0.2)
    status, body, _ = call("/api/command", {"command": "run"}, auth) if status == 200 else (status, "", None)
    say(status == 409 and "not commissioned" in body,
        "console: before commissioning, run is refused by the gate: %s %s" % (status, body))
    open(gated, "w").close()

state = None
for _ in range(200 if gated else 100):
    try:
        status, body, _ = call("/api/state")
        state = json.loads(body)
        if state.get("state") == "running":
            break
    except (OSError, ValueError):
        pass
    time.sleep(0.2)
say(state is not None and state.get("state") == "running",
    "console: the live state is open to view: %s" % (state or {}).get("state"))
status, page, _ = call("/")
say(status == 200 and "Transplanter console" in page, "console: the page loads (%d)" % status)
status, body, _ = call("/api/command", {"command": "set_depth_mm", "value": 90})
say(status == 401, "console: a command without a session gets %d" % status)
status, auth = log_in()
say(status == 200 and auth["Cookie"], "console: the operator logs in with the pairing secret (%d)" % status)
status, body, _ = call("/api/command", {"command": "record_start"}, auth)
console_rec = json.loads(body).get("message", "").replace("recording to ", "") if status == 200 else ""
say(status == 200 and console_rec.startswith("console-"), "console: record_start: %d %s" % (status, body))
time.sleep(0.5)
sent = time.time()
status, body, _ = call("/api/command", {"command": "set_depth_mm", "value": 90}, auth)
say(status == 200, "console: set_depth_mm 90: %d %s" % (status, body))
status, body, _ = call("/api/command", {"command": "set_depth_mm", "value": 300}, auth)
say(status == 422 and "nothing changed" in body, "console: set_depth_mm 300: %d %s" % (status, body))
# The recording is flushed every 200 ms: the new target must be there within 1 s.
seen = None
while time.time() - sent < 3 and seen is None:
    lines = [l for l in open(recording).read().splitlines() if l and not l.startswith("#")]
    col = lines[0].split(",").index("depth_target_mm")
    if any(l.count(",") == lines[0].count(",") and float(l.split(",")[col]) == 90.0
           for l in lines[1:]):
        seen = time.time() - sent
    time.sleep(0.05)
say(seen is not None and seen <= 1.0, "console: the depth target reached the recording in %s"
    % ("%.2f s" % seen if seen is not None else "more than 3 s"))
status, body, _ = call("/api/command", {"command": "record_stop"}, auth)
say(status == 200 and "closed" in body, "console: record_stop: %d %s" % (status, body))
rec_path = os.path.join(os.path.dirname(os.path.abspath(recording)), console_rec)
rows = [l for l in open(rec_path).read().splitlines() if l and not l.startswith("#")] if console_rec else []
col = rows[0].split(",").index("depth_target_mm") if rows else 0
say(len(rows) > 50 and any(float(r.split(",")[col]) == 90.0 for r in rows[1:]),
    "console: the console's recording %s has %d rows, the new target among them" % (console_rec, len(rows) - 1))
status, got, _ = call("/api/recordings/" + console_rec)
say(status == 200 and got == open(rec_path).read() if console_rec else False,
    "console: the console's recording downloads whole (%d, %d bytes)" % (status, len(got)))
codes = [call("/api/login", {"secret": "wrong-%d" % i})[0] for i in range(7)]
say(codes == [401] * 5 + [429] * 2, "console: 7 wrong secrets: %s" % codes)
status, body, _ = call("/api/recordings")
names = [r["name"] for r in json.loads(body).get("recordings", [])] if status == 200 else []
say(os.path.basename(recording) in names and console_rec in names,
    "console: the recordings are offered: %s" % names)
audit = open(audit_path).read()
for words in ('set_depth_mm value=90 result="accepted"', "set_depth_mm value=300",
              'login value=- result="logged in as operator"', 'result="wrong secret"'):
    say(words in audit, "console: the audit log has " + words)
sys.exit(fail)
