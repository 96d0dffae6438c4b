#!/usr/bin/env bash
# The README's sweep command, shortened: replicated runs of the Box-Behnken design, the response
# surfaces with lack of fit, the optimum inside the design, and the report. Exit 1 on a failure.
set -u
sim=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=$("$sim" sweep "$src/scenarios/zhangqiu-field.toml" --out "$tmp/sweep" --distance 2 \
  --replicates 2 --max-replicates 2 --jobs 2 2>&1)
rc=$?
echo "$out"
[ $rc -eq 0 ] || { echo "FAIL sweep exited $rc"; exit 1; }
/usr/bin/python3 - "$tmp/sweep" <<'PY' || exit 1
import json, sys
d = sys.argv[1]
j = json.load(open(d + "/sweep.json"))
runs = open(d + "/sweep.csv").read().splitlines()[1:]
fail = []
if j["runs"] != 30 or len(runs) != j["runs"]:
    fail.append("runs %s, csv rows %d (want 30 and 30)" % (j["runs"], len(runs)))
for resp in ("uprightness", "damage", "seedling_peak_force"):
    terms = [t["term"] for t in j[resp]["terms"]]
    if terms != ["A", "B", "C", "AB", "AC", "BC", "A^2", "B^2", "C^2"]:
        fail.append("%s terms %s" % (resp, terms))
    if "lack_of_fit" not in j[resp]:
        fail.append("%s has no lack of fit with replicates" % resp)
o = j["optimum"]
if not (105 <= o["contact_area_mm2"] <= 405 and 0.15 <= o["disc_speed_radps"] <= 0.35
        and 40 <= o["depth_mm"] <= 160 and 0 < o["desirability"] <= 1):
    fail.append("optimum outside the design: %s" % o)
html = open(d + "/report.html").read()
for want in ("paper's optimum", "lack of fit", "model assumptions", "<svg"):
    if want not in html.lower():
        fail.append("report.html lacks %r" % want)
print("\n".join("FAIL " + f for f in fail) or "ok   sweep: %d runs, optimum %.0f mm^2 %.3f rad/s %.0f mm"
      % (j["runs"], o["contact_area_mm2"], o["disc_speed_radps"], o["depth_mm"]))
sys.exit(1 if fail else 0)
PY
