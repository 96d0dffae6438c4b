#!/usr/bin/env bash
# The README's sweep command, whole, against what the paper found (issue 16): an interior
# maximum of uprightness in disc speed and in depth, the optimum within 10 % of the paper's
# 0.278 rad/s and 102 mm, the centre point within 2 points of 94.8 % upright and 1 point of 3 %
# damaged. Nothing is tuned per point. Exit 1 on a failure.
set -u
sim=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=$("$sim" sweep "$src/scenarios/zhangqiu-field.toml" --out "$tmp/sweep" 2>&1)
rc=$?
echo "$out"
[ $rc -eq 0 ] || { echo "FAIL sweep exited $rc"; exit 1; }
/usr/bin/python3 - "$tmp/sweep" "$out" <<'PY' || exit 1
import json, sys
j = json.load(open(sys.argv[1] + "/sweep.json"))
out = sys.argv[2]
fail = []
for factor in ("disc speed", "depth"):
    if "interior maximum of uprightness in %s: yes" % factor not in out:
        fail.append("no interior maximum of uprightness in " + factor)
o = j["optimum"]
for key, paper in (("disc_speed_radps", 0.278), ("depth_mm", 102.0)):
    if abs(o[key] / paper - 1) > 0.10:
        fail.append("optimum %s %.3f, more than 10 %% from the paper's %g" % (key, o[key], paper))
if abs(j["centre_uprightness_pct"] - 94.8) > 2.0:
    fail.append("centre uprightness %.2f %%, paper 94.8" % j["centre_uprightness_pct"])
if abs(j["centre_damage_pct"] - 3.0) > 1.0:
    fail.append("centre damage %.2f %%, paper 3" % j["centre_damage_pct"])
print("\n".join("FAIL " + f for f in fail) or
      "ok   the paper's findings: optimum %.3f rad/s %.0f mm, centre %.2f %% upright %.2f %% damaged"
      % (o["disc_speed_radps"], o["depth_mm"], j["centre_uprightness_pct"], j["centre_damage_pct"]))
sys.exit(1 if fail else 0)
PY
