#!/usr/bin/env bash
# The operator's console in a real browser (Debian's chromium, headless), against
# `planter-sim live` on the field scenario, as the README says to start it:
# - the page loads with no script error and fetches nothing from outside the machine;
# - live values change: two loads seconds apart show different times and states;
# - the charts are drawn;
# - a request that is not a page of the console is refused, and a large body is refused;
# - a second console on the same port says it cannot listen and exits non-zero;
# - a screenshot of the console is kept in SHOTS (the build directory).
# Usage: console_browser_test.sh PLANTER_SIM SOURCE_DIR SHOTS
set -u
sim=$1 src=$2 shots=$3
work=$(mktemp -d)
server=
cleanup() { [ -n "$server" ] && kill "$server" 2>/dev/null; wait 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
mkdir -p "$shots"
browser=$(command -v chromium || true)
[ -n "$browser" ] || { echo "FAIL chromium is not installed (scripts/setup.sh installs it)"; exit 1; }

# Any free port; the console says which on its first line.
"$sim" live "$src/scenarios/zhangqiu-field.toml" --port 0 --duration 120 >"$work/live.out" 2>&1 &
server=$!
for _ in $(seq 1 100); do grep -q '^console: http' "$work/live.out" && break; sleep 0.1; done
url=$(sed -n 's|^console: \(http://[^ ]*\) .*|\1|p' "$work/live.out" | head -1)
[ -n "$url" ] || { echo "FAIL planter-sim live did not start:"; cat "$work/live.out"; exit 1; }
echo "console at $url"
sleep 6  # the machine boots its nodes and starts planting

flags=(--headless=new --no-sandbox --disable-gpu --hide-scrollbars --no-first-run
  --user-data-dir="$work/profile" --enable-logging=stderr --v=0 --virtual-time-budget=5000)
timeout 60 "$browser" "${flags[@]}" --dump-dom "$url" >"$work/first.dom" 2>"$work/first.console"
sleep 3
timeout 60 "$browser" "${flags[@]}" --dump-dom "$url" >"$work/second.dom" 2>"$work/second.console"
timeout 60 "$browser" "${flags[@]}" --window-size=1000,1600 --screenshot="$shots/console.png" \
  "$url" >/dev/null 2>&1
curl -s "$url" >"$work/page.html"
not_found=$(curl -s -o /dev/null -w '%{http_code}' "$url/api/nothing")
post=$(curl -s -o /dev/null -w '%{http_code}' -X POST --data 'x=1' "$url/api/state")
big=$(head -c 100000 /dev/zero | tr '\0' 'a' | curl -s -o /dev/null -w '%{http_code}' -X POST \
  --data-binary @- "$url/api/state")
csp=$(curl -s -D - -o /dev/null "$url" | grep -i '^content-security-policy' || true)
# A second console on the same port must say so and stop, not share the port.
port=${url##*:}; port=${port%/}
second=0
"$sim" live "$src/scenarios/zhangqiu-field.toml" --port "$port" --duration 1 >"$work/second.out" 2>&1 || second=$?
grep -q "cannot listen on 127.0.0.1:$port" "$work/second.out" || second=0

/usr/bin/python3 - "$work" "$shots/console.png" "$not_found" "$post" "$big" "$csp" "$second" <<'PY'
import os, re, sys
work, shot, not_found, post, big, csp, second = sys.argv[1:]
page = open(os.path.join(work, "page.html")).read()
fail = []
def dom(name):
    return open(os.path.join(work, name + ".dom")).read()
def console(name):
    text = open(os.path.join(work, name + ".console"), errors="replace").read()
    return [l for l in text.splitlines() if "CONSOLE" in l and ("Uncaught" in l or "Error" in l)]
for name in ("first", "second"):
    if console(name):
        fail.append("%s load: script errors: %s" % (name, " | ".join(console(name)[:3])))
if re.search(r"<(script|link|img)[^>]+(src|href)=['\"]?(https?:)?//", page, re.I):
    fail.append("the page fetches from the network")
times = []
for name in ("first", "second"):
    d = dom(name)
    m = re.search(r'data-updates="(\d+)"', d)
    t = re.search(r'data-t="([0-9.]+)"', d)
    if not m or int(m.group(1)) < 2:
        fail.append("%s load: the live values did not update" % name)
    times.append(float(t.group(1)) if t else None)
    for chart in ("chart_v", "chart_sigma", "chart_force", "chart_depth"):
        parts = d.split('id="%s"' % chart, 1)
        body = parts[1].split('class="chart"', 1)[0] if len(parts) == 2 else ""
        if "<canvas" not in body:
            fail.append("%s load: %s not drawn" % (name, chart))
    if not re.search(r'id="seedlings">\d+<', d):
        fail.append("%s load: the planting monitor shows no count" % name)
if None in times or times[1] <= times[0]:
    fail.append("live time did not advance between loads: %s" % times)
if not_found != "404":
    fail.append("an unknown path answered %s, not 404" % not_found)
if post not in ("404", "405"):
    fail.append("a POST to the viewer answered %s" % post)
if big not in ("404", "405", "413"):
    fail.append("a 100 kB body answered %s" % big)
if "default-src 'none'" not in csp:
    fail.append("no content security policy: %r" % csp)
if not os.path.exists(shot) or os.path.getsize(shot) < 10000:
    fail.append("no screenshot")
if second == "0":
    fail.append("a second console on the same port did not refuse with its message")
print("\n".join("FAIL " + f for f in fail) or
      "ok   console: live values at t %.1f then %.1f s, charts drawn, no script error, nothing "
      "fetched from outside, unknown paths 404, POST %s, 100 kB body %s, a second console on "
      "the port refused; %s"
      % (times[0], times[1], post, big, shot))
sys.exit(1 if fail else 0)
PY
