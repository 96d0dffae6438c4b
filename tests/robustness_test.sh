#!/usr/bin/env bash
# planter-sim robustness as the README runs it, with 2 random combinations and short routes:
# the table and the benchmark line printed, robustness.json whole, and verdicts that can fail:
# the nominal case holds every loop; the cases the loops cannot hold are alarmed by the alarm
# of their own (the disc too slow for the speed, a load cell off by a fifth, a depth past the
# end stop... of the suite's own cases); the paper's drive is beside each case; the same seed
# gives the same suite. Exit 1 on a failure.
set -u
sim=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp" "$tmp".runs' EXIT
for o in a b; do
  "$sim" robustness "$src/scenarios/zhangqiu-field.toml" --combinations 2 --distance 6 --jobs 2 \
    --out "$tmp/$o" >"$tmp/$o.log" 2>&1 || { cat "$tmp/$o.log"; echo "FAIL robustness exited"; exit 1; }
done
cat "$tmp/a.log"
tail -1 "$tmp/a.log" | grep -Eq '^robustness: [0-9]+ of [0-9]+ cases held, [0-9]+ silent$' ||
  { echo "FAIL the last line is not the benchmark line"; exit 1; }
for f in robustness.json robustness.csv report.html run.json; do
  [ -s "$tmp/a/$f" ] || { echo "FAIL $f missing"; exit 1; }
done
cmp -s "$tmp/a/robustness.csv" "$tmp/b/robustness.csv" ||
  { echo "FAIL the same seed gave another suite"; exit 1; }
/usr/bin/python3 - "$tmp/a" <<'PY' || exit 1
import json, sys
j = json.load(open(sys.argv[1] + "/robustness.json"))
cases = {c["case"]: c for c in j["cases"]}
fail = []
def verdict(case, loop):
    return cases[case]["loops"][loop]["verdict"]
for loop in ("sigma", "clamp", "depth"):
    if verdict("nominal", loop) != "held":
        fail.append("nominal %s: %s" % (loop, verdict("nominal", loop)))
for case, loop, bit in (("faster than the disc", "sigma", 1), ("load cell span -20 %", "clamp", 4),
                        ("softer lips mid-run", "clamp", 4)):
    if verdict(case, loop) != "alarmed":
        fail.append("%s: %s %s, not alarmed" % (case, loop, verdict(case, loop)))
    if not cases[case]["warnings_seen"] & (1 << bit):
        fail.append("%s: warning bit %d never raised" % (case, bit))
if cases["e-stop"]["faults"] != 0 and verdict("e-stop", "clamp") == "silent":
    fail.append("e-stop counted silent")
held = sum(c["verdict"] == "held" for c in j["cases"])
silent = sum(c["verdict"] == "silent" for c in j["cases"])
if (held, silent) != (j["held"], j["silent"]) or j["cases_total"] != len(j["cases"]):
    fail.append("the counts do not add up")
if len(j["cases"]) < 30 or sum(c["case"].startswith("combination") for c in j["cases"]) != 2:
    fail.append("%d cases" % len(j["cases"]))
comparable = [c for c in j["cases"] if c["paper_drive"]["sigma"] is not None]
if len(comparable) < 20:
    fail.append("the paper's drive beside only %d cases" % len(comparable))
if fail:
    print("FAIL " + "; ".join(fail))
    sys.exit(1)
print("robustness: %d cases, nominal held, the unholdable ones alarmed by their own alarms" % len(j["cases"]))
PY
if "$sim" robustness "$src/scenarios/zhangqiu-field.toml" --combinations -1 --out "$tmp/bad" >"$tmp/bad.log" 2>&1; then
  echo "FAIL --combinations -1 was accepted"
  exit 1
fi
grep -q -- "--combinations" "$tmp/bad.log" || { cat "$tmp/bad.log"; echo "FAIL refused without naming the option"; exit 1; }
echo "PASS robustness"
