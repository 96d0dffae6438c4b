#!/usr/bin/env bash
# The README's sweep command, whole (issue 27). The paper's findings are printed beside the
# model's, never a target: this test checks that both are there, that the report carries every
# model value with its origin and range, and that the clamp force's trade-off exists in the
# model (damage does not fall as the force rises; grip is paid for below the force where the
# soil turns seedlings in the clamp). Exit 1 on a failure.
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
d = sys.argv[1]
j = json.load(open(d + "/sweep.json"))
out = sys.argv[2]
html = open(d + "/report.html").read()
fail = []
for key in ("contact_area_mm2", "disc_speed_radps", "depth_mm"):
    if key not in j["optimum"] or key not in j["paper_optimum"]:
        fail.append("optimum or paper's optimum lacks " + key)
if j["paper_centre"] != {"uprightness_pct": 94.8, "damage_pct": 3.0}:
    fail.append("the paper's centre point is not beside the model's")
if "paper: 255 mm^2, 0.278 rad/s, 102 mm" not in out.splitlines()[-1]:
    fail.append("the last line does not print the paper's optimum beside the model's")
# The constant forces, then the clamp that grips each stem under its own ceiling (issue 50).
per_stem = [c for c in j["force_curve"] if c.get("grip") == "per stem"]
curve = [c for c in j["force_curve"] if c.get("grip") == "constant"]
forces = [c["clamp_force_N"] for c in curve]
if forces != [40, 60, 80, 90, 100, 120]:
    fail.append("force curve set-points %s" % forces)
if len(per_stem) != 1 or j["force_curve"][-1] is not per_stem[0]:
    fail.append("the per-stem grip is not the force table's last row")
damage = [c["damage_pct"] for c in curve]
if any(b < a - 1e-9 for a, b in zip(damage, damage[1:])):
    fail.append("damage falls as the clamp force rises: %s" % damage)
turned = [c["turned_in_clamp"] for c in curve]
if any(b > a for a, b in zip(turned, turned[1:])):
    fail.append("more seedlings turn in the clamp with more grip: %s" % turned)
for key in ("seedlings.strength_mean_N", "soil.cohesion_kPa", "mechanism.root_clearance_mm",
            "seedlings.tilt_noise_deg"):
    if key not in html:
        fail.append("the report's model values lack " + key)
for word in ("measured", "assumed", "calibrated", "design"):
    if "<td>%s</td>" % word not in html:
        fail.append("no value of origin '%s' in the report" % word)
print("\n".join("FAIL " + f for f in fail) or
      "ok   model: optimum %.0f mm^2 %.3f rad/s %.0f mm, centre %.2f %% upright %.2f %% damaged; "
      "paper: 255 mm^2 0.278 rad/s 102 mm, 94.8 %% and 3 %%; damage over 40-120 N: %s"
      % (j["optimum"]["contact_area_mm2"], j["optimum"]["disc_speed_radps"],
         j["optimum"]["depth_mm"], j["centre_uprightness_pct"], j["centre_damage_pct"],
         " ".join("%.2f" % x for x in damage)))
sys.exit(1 if fail else 0)
PY
