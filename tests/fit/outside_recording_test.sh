#!/usr/bin/env bash
# planter-fit on a recording from a mechanism it was not built around (a second-order speed
# loop, irregular ~50 Hz sampling, only the disc drive's columns, Coulomb friction): it must
# name Coulomb friction on the torque, not Stribeck friction (which holds it and would fit as
# well), and at least halve the held-out torque error.
set -euo pipefail
tool=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$src/tests/fit/outside_drive_recording.py" "$work/outside.csv"
"$tool" "$work/outside.csv" --out "$work/fit" >"$work/summary.txt"
cat "$work/summary.txt"
/usr/bin/python3 - "$work/fit/fit.json" <<'PY'
import json, sys
fit = json.load(open(sys.argv[1]))
torque = next(c for c in fit["channels"] if c["output"] == "disc_torque")
names = [e["effect"] for e in torque["effects"]]
before, after = torque["held_out_rms"]["nominal"], torque["held_out_rms"]["augmented"]
ok = "Coulomb friction" in names and "Stribeck friction" not in names and after <= 0.5 * before
print("%s outside recording: disc_torque named %s, held-out RMS %.4g -> %.4g"
      % ("PASS" if ok else "FAIL", names or "nothing", before, after))
sys.exit(0 if ok else 1)
PY
