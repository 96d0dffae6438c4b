#!/usr/bin/env bash
# Every report, opened in a real browser (Debian's chromium, headless): planter-sim's run,
# sweep, robustness and sensitivity, planter-fit's and planter-dem's compression. For each: the page loads with no script error, every
# chart is drawn (a dygraphs canvas with its title and legend under each chart element), nothing
# is fetched from the network, and a screenshot is kept in SHOTS (the build directory). Then each
# on a phone (390 x 844, tests/report_phone_test.py): the page fits the screen's width.
# Usage: report_browser_test.sh PLANTER_SIM PLANTER_FIT PLANTER_DEM SOURCE_DIR SHOTS
set -u
sim=$1 fit=$2 dem=$3 src=$4 shots=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
mkdir -p "$shots"
browser=$(command -v chromium || true)
[ -n "$browser" ] || { echo "FAIL chromium is not installed (scripts/setup.sh installs it)"; exit 1; }

run() { "$@" >"$work/log" 2>&1 || { echo "FAIL $*:"; tail -20 "$work/log"; exit 1; }; }
run "$sim" run "$src/scenarios/demo-hidden-effect.toml" --quiet --out "$work/run"
run "$fit" "$work/run/recording.csv" --out "$work/fit"
printf '[bond]\nnormal_stiffness_N_m3 = 3.5e6\nshear_stiffness_N_m3 = 3.5e6\ntensile_strength_Pa = 8.5e3\nshear_strength_Pa = 8.5e3\n[test]\nstroke_mm = 2\n' >"$work/short.toml"
run "$dem" compress --params "$work/short.toml" --speedup 100 --out "$work/dem"
run "$sim" sweep "$src/scenarios/zhangqiu-field.toml" --out "$work/sweep" --distance 2 \
  --replicates 2 --max-replicates 2 --jobs 2
run "$sim" robustness "$src/scenarios/zhangqiu-field.toml" --out "$work/robustness" --distance 3 \
  --combinations 1 --jobs 2
run "$sim" sensitivity "$src/scenarios/zhangqiu-field.toml" --out "$work/sensitivity" \
  --trajectories 2 --distance 0.5 --jobs 2

for report in run fit dem sweep robustness sensitivity; do
  page="$work/$report/report.html"
  flags=(--headless=new --no-sandbox --disable-gpu --hide-scrollbars --no-first-run
    --user-data-dir="$work/profile" --enable-logging=stderr --v=0)
  timeout 60 "$browser" "${flags[@]}" --dump-dom "file://$page" >"$work/$report.dom" 2>"$work/$report.console"
  timeout 60 "$browser" "${flags[@]}" --window-size=1000,2400 \
    --screenshot="$shots/$report.png" "file://$page" >/dev/null 2>&1
  /usr/bin/python3 - "$report" "$page" "$work/$report.dom" "$work/$report.console" "$shots/$report.png" <<'PY' || fails=$((fails + 1))
import os, re, sys
name, page, dom_file, console_file, shot = sys.argv[1:]
html = open(page).read()
dom = open(dom_file).read()
console = open(console_file, errors="replace").read()
fail = []
errors = [l for l in console.splitlines() if "CONSOLE" in l and ("Uncaught" in l or "Error" in l)]
if errors:
    fail.append("script errors: " + " | ".join(errors[:3]))
if re.search(r"<(script|link|img)[^>]+(src|href)=['\"]?(https?:)?//", html, re.I):
    fail.append("fetches from the network")
charts = re.findall(r"<div class=\"plot\" id=\"(chart\d+)\"", dom)
want = len(re.findall(r"<div class='plot' id='chart\d+'>", html))
for c in charts:
    body = dom.split('id="%s"' % c, 1)[1].split('id="%s-legend"' % c, 1)
    if "<canvas" not in body[0] or "dygraph-title" not in body[0]:
        fail.append("%s not drawn" % c)
    elif len(body) < 2 or not re.search(r"<span[^>]*>", body[1].split("</div>", 1)[0]):
        fail.append("%s has no legend" % c)
if len(charts) != want:
    fail.append("%d chart elements in the page, %d in the browser's document" % (want, len(charts)))
if not os.path.exists(shot) or os.path.getsize(shot) < 10000:
    fail.append("no screenshot")
if name not in ("sweep", "sensitivity") and want == 0:
    fail.append("no charts")
print("\n".join("FAIL %s: %s" % (name, f) for f in fail) or
      "ok   %s: %d charts drawn, no script error, nothing fetched; %s" % (name, want, shot))
sys.exit(1 if fail else 0)
PY
done
timeout 120 /usr/bin/python3 "$src/tests/report_phone_test.py" "$shots" run="$work/run/report.html" \
  fit="$work/fit/report.html" dem="$work/dem/report.html" sweep="$work/sweep/report.html" \
  robustness="$work/robustness/report.html" sensitivity="$work/sensitivity/report.html" ||
  fails=$((fails + 1))
[ "$fails" -eq 0 ] && echo "reports in a browser: all drawn, and each fits a phone" || exit 1
