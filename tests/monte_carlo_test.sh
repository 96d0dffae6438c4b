#!/usr/bin/env bash
# planter-sim montecarlo as the docs show it, small (8 runs of 3 m): one row a run, every value
# inside its plausible range with each range's strata covered once (a Latin hypercube), the
# quantiles ordered and bracketing the runs, the same seed giving the same study, and too few
# runs refused with a message. Exit 1 on a failure.
set -u
sim=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for o in a b; do
  "$sim" montecarlo "$src/scenarios/zhangqiu-field.toml" --runs 8 --distance 3 --jobs 2 \
    --out "$tmp/$o" >"$tmp/$o.log" 2>&1 || { cat "$tmp/$o.log"; echo "FAIL montecarlo exited"; exit 1; }
done
cat "$tmp/a.log"
cmp -s "$tmp/a/montecarlo.json" "$tmp/b/montecarlo.json" ||
  { echo "FAIL the same seed gave another study"; exit 1; }
# A torn summary.json beside a whole run.json (issue 53, item 4): its size is not the one the
# manifest records, so the run is run again and the study comes out the same.
torn=$tmp/a.runs/runs/runs/00000/summary.json
[ -f "$torn" ] || { echo "FAIL no run's summary at $torn"; exit 1; }
head -c 100 "$torn" >"$tmp/torn" && cat "$tmp/torn" >"$torn"
"$sim" montecarlo "$src/scenarios/zhangqiu-field.toml" --runs 8 --distance 3 --jobs 2 \
  --out "$tmp/a" --force >"$tmp/a2.log" 2>&1 || { cat "$tmp/a2.log"; echo "FAIL a torn run's summary stopped the study"; exit 1; }
cmp -s "$tmp/a/montecarlo.json" "$tmp/b/montecarlo.json" ||
  { echo "FAIL the study with a torn run's summary run again differs"; exit 1; }
echo "a torn summary.json was run again"
# Two tools on one plan's folder (issue 53, item 5): while another holds the folder's lock
# (here flock(1), as a running sweep would), the second is refused at once, with one line.
mkdir -p "$tmp/c.runs/runs"
if flock "$tmp/c.runs/runs/.planter.lock" "$sim" montecarlo "$src/scenarios/zhangqiu-field.toml" \
  --runs 8 --distance 3 --jobs 2 --out "$tmp/c" >"$tmp/c.log" 2>&1; then
  cat "$tmp/c.log"; echo "FAIL a second tool ran on a plan folder another holds"; exit 1
fi
grep -q "c.runs/runs: another planter-sim is running this plan now" "$tmp/c.log" ||
  { cat "$tmp/c.log"; echo "FAIL the busy plan folder was not said"; exit 1; }
echo "a plan folder another tool holds is refused: $(tail -1 "$tmp/c.log")"

/usr/bin/python3 - "$tmp/a" <<'PY' || exit 1
import csv, json, math, sys
j = json.load(open(sys.argv[1] + "/montecarlo.json"))
rows = list(csv.DictReader(open(sys.argv[1] + "/montecarlo.csv")))
fail = []
if len(rows) != 8 or j["runs"] != 8:
    fail.append("%d rows for 8 runs" % len(rows))
if len({r["seed"] for r in rows}) != 8:
    fail.append("runs share a seed")
for v in j["values"]:
    lo, hi = v["range"]
    col = [float(r[v["key"]]) for r in rows]
    if hi <= lo:
        continue
    strata = sorted(min(7, int(math.floor(8 * (c - lo) / (hi - lo)))) for c in col)
    # 6 digits in the CSV: the range check allows for the rounding.
    if min(col) < lo - 1e-6 * abs(hi) or max(col) > hi + 1e-6 * abs(hi):
        fail.append("%s outside its range" % v["key"])
    elif strata != list(range(8)):
        fail.append("%s does not cover its 8 strata once each: %s" % (v["key"], strata))
for name, col in (("uprightness", "uprightness_pct"), ("damage", "damage_pct")):
    f = j["figures"][name]
    runs = [float(r[col]) for r in rows]
    if not (min(runs) - 1e-6 <= f["p5"] <= f["median"] <= f["p95"] <= max(runs) + 1e-6):
        fail.append("%s's quantiles do not bracket the runs in order" % name)
    if abs(f["mean"] - sum(runs) / len(runs)) > 1e-4 * max(1.0, abs(f["mean"])):
        fail.append("%s's mean is not the runs' mean" % name)
if fail:
    print("FAIL " + "; ".join(fail))
    sys.exit(1)
print("montecarlo: 8 runs, %d values each across its range, quantiles bracket the runs" % len(j["values"]))
PY
if "$sim" montecarlo "$src/scenarios/zhangqiu-field.toml" --runs 1 --out "$tmp/one" >"$tmp/one.log" 2>&1; then
  echo "FAIL --runs 1 was accepted"
  exit 1
fi
grep -q -- "--runs" "$tmp/one.log" || { cat "$tmp/one.log"; echo "FAIL --runs 1 refused without naming it"; exit 1; }
[ ! -e "$tmp/one" ] || { echo "FAIL a refused study left an output folder"; exit 1; }
echo "PASS montecarlo"
