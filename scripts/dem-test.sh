#!/usr/bin/env bash
# The seedling DEM's figures, printed: the compression test with the paper's parameters and
# with the calibrated ones, the paper's calibration workflow (Plackett-Burman, steepest
# ascent, Box-Behnken), the reduced-order model, and the speed against Yade on one core.
# Usage: scripts/dem-test.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=$build/dem-test
mkdir -p "$out"
dem=$build/apps/planter-dem/planter-dem
echo "-- compression, the paper's parameters (S = 4.842e9 N/m^3, sigma_c = 5.643e7 Pa)"
"$dem" compress --out "$out/paper" | tail -2
echo "-- compression, models/seedling_dem.toml"
"$dem" compress --params "$root/models/seedling_dem.toml" --out "$out/calibrated" | tail -2
# The calibrated bonds hold at the particle size they were tuned at (1.5 mm radius) only: the
# same parameters with finer or coarser particles give another seedling (issue 27, item 5).
echo "-- the same parameters at other particle radii (the calibration's resolution: 1.5 mm)"
for r in 1.0 1.25 2.0; do
  { cat "$root/models/seedling_dem.toml"; printf '\n[seedling]\nparticle_radius_mm = %s\n' "$r"; } \
    >"$out/particles-$r.toml"
  printf 'particle radius %s mm: ' "$r"
  "$dem" compress --params "$out/particles-$r.toml" --out "$out/particles-$r" --force | tail -1
done
echo "-- calibration workflow to 140.6 N (all cores; resumes from $out/calibrate/runs)"
"$dem" calibrate --target 140.6 --target-displacement-mm 4 --out "$out/calibrate" 2>/dev/null
echo "-- the calibration's report on a phone (390 x 844: tests/phone_checks.js)"
/usr/bin/python3 "$root/tests/report_phone_test.py" "$out" calibrate="$out/calibrate/report.html"
echo "-- reduced-order model over the paper's diameters"
"$dem" reduce --params "$root/models/seedling_dem.toml" --out "$out/reduce" | tail -2
echo "-- speed against Yade on the same compression test"
"$root/scripts/apt-install.sh" dem-test yade
"$build/bench/planter_bench_dem" "$root/bench/dem/yade_compression.py" "$out" 6000
