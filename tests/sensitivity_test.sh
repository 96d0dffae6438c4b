#!/usr/bin/env bash
# planter-sim sensitivity as the README shows it, small (2 trajectories of 3 m): every model
# value is ranked for each figure, the runs are r (k + 1), the spread brackets the runs, and
# the same seed gives the same analysis. `planter-sim values` lists the same values. Exit 1 on a
# failure.
set -u
sim=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for o in a b; do
  "$sim" sensitivity "$src/scenarios/zhangqiu-field.toml" --trajectories 2 --distance 3 \
    --out "$tmp/$o" >"$tmp/$o.log" 2>&1 || { cat "$tmp/$o.log"; echo "FAIL sensitivity exited"; exit 1; }
done
cat "$tmp/a.log"
cmp -s "$tmp/a/sensitivity.json" "$tmp/b/sensitivity.json" || { echo "FAIL the same seed gave another analysis"; exit 1; }
"$sim" values "$src/scenarios/zhangqiu-field.toml" >"$tmp/values.txt" || { echo "FAIL values exited"; exit 1; }
/usr/bin/python3 - "$tmp/a" "$tmp/values.txt" <<'PY' || exit 1
import csv, json, sys
j = json.load(open(sys.argv[1] + "/sensitivity.json"))
rows = list(csv.DictReader(open(sys.argv[1] + "/sensitivity.csv")))
listed = [l.split()[0] for l in open(sys.argv[2]).read().splitlines()[1:]]
fail = []
k = len(j["values"])
if [v["key"] for v in j["values"]] != listed:
    fail.append("planter-sim values and the analysis list different values")
if j["points"] != 2 * (k + 1) or len(rows) != j["points"] or j["runs"] != j["points"]:
    fail.append("%d points for %d values and 2 trajectories" % (len(rows), k))
for fig in ("uprightness", "damage", "turned in the clamp"):
    ranks = sorted(v[fig]["rank"] for v in j["values"])
    if ranks != list(range(1, k + 1)):
        fail.append("the ranks of %s are not 1..%d" % (fig, k))
up = [float(r["uprightness_pct"]) for r in rows]
s = j["spread"]["uprightness"]
near = lambda a, b: abs(a - b) <= 1e-4 * max(1.0, abs(b))  # the CSV has 6 digits
if not (near(s["min"], min(up)) and near(s["max"], max(up)) and s["min"] <= s["median"] <= s["max"]):
    fail.append("the uprightness spread does not bracket the runs")
for v in j["values"]:
    lo, hi = v["range"]
    col = [float(r[v["key"]]) for r in rows]
    if min(col) < lo - 1e-9 or max(col) > hi + 1e-9:
        fail.append(v["key"] + " left its plausible range")
print("\n".join("FAIL " + f for f in fail) or "ok   %d values ranked over %d runs" % (k, len(rows)))
sys.exit(1 if fail else 0)
PY
