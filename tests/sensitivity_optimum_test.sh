#!/usr/bin/env bash
# planter-sim sensitivity --optimum, small (2 trajectories of 3 m, each point with the paper's
# 15-run design around it): the optimum's coordinates are found at every point, inside the
# design, their spread is given with a verdict per finding, and the line with the paper's
# optimum is printed beside it. Exit 1 on a failure.
set -u
sim=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$sim" sensitivity "$src/scenarios/zhangqiu-field.toml" --trajectories 2 --distance 3 --optimum \
  --out "$tmp/s" >"$tmp/log" 2>&1 || { cat "$tmp/log"; echo "FAIL sensitivity --optimum exited"; exit 1; }
cat "$tmp/log"
/usr/bin/python3 - "$tmp/s" "$tmp/log" <<'PY' || exit 1
import csv, json, sys
j = json.load(open(sys.argv[1] + "/sensitivity.json"))
rows = list(csv.DictReader(open(sys.argv[1] + "/sensitivity.csv")))
log = open(sys.argv[2]).read()
fail = []
k = len(j["values"])
if j["points"] != 2 * (k + 1) or j["runs"] != 16 * j["points"]:
    fail.append("%d points, %d runs: expected 2 (k + 1) points of 1 + 15 runs" % (j["points"], j["runs"]))
bounds = {"optimum_contact_area_mm2": (105, 405), "optimum_disc_speed_radps": (0.15, 0.35),
          "optimum_depth_mm": (40, 160)}
for col, (lo, hi) in bounds.items():
    vals = [float(r[col]) for r in rows]
    if min(vals) < lo - 1e-6 or max(vals) > hi + 1e-6:
        fail.append("%s left the design: %g-%g" % (col, min(vals), max(vals)))
for name in ("optimum contact area", "optimum disc speed", "optimum depth", "uprightness"):
    sp = j["spread"].get(name)
    if sp is None or not isinstance(sp.get("holds"), bool):
        fail.append("no verdict for " + name)
    elif sp["holds"] != (sp["p95"] - sp["p5"] <= sp["holds_within"]):
        fail.append("the verdict for %s does not follow its rule" % name)
    if name + " " not in log:
        fail.append("the verdict for %s is not printed" % name)
terms = j.get("significant_terms", {})
if sorted(terms) != sorted(["A", "B", "C", "AB", "AC", "BC", "A^2", "B^2", "C^2"]) or \
        any(not 0 <= v["share_of_points"] <= 1 for v in terms.values()):
    fail.append("no share of points for every term of the quadratic")
if len(j.get("paper_terms_holding", [])) + len(j.get("paper_terms_not_holding", [])) != 9:
    fail.append("every term is not judged")
if "terms of uprightness significant (paper's: A B C BC A^2 B^2 C^2)" not in log:
    fail.append("the terms' line is not printed")
if "paper: 255 mm^2, 0.278 rad/s, 102 mm" not in log:
    fail.append("the paper's optimum is not printed beside the spread")
print("\n".join("FAIL " + f for f in fail) or "ok   optimum found at %d points" % len(rows))
sys.exit(1 if fail else 0)
PY
