#!/usr/bin/env bash
# The blind proof of planter-fit: field-like recordings made with planter-sim in closed loop
# (the controller runs the machine as in the field), with an effect hidden in the plant, at
# several noise levels and with nominal parameters perturbed; planter-fit sees only the
# recording. Prints PASS/FAIL per case and the count last.
# Usage: scripts/fit-proof.sh BUILD_DIR [OUT_DIR]
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=${2:-$build/fit-proof}
mkdir -p "$out"
sim=$build/apps/planter-sim/planter-sim
fit=$build/apps/planter-fit/planter-fit
# The base scenario (scripts/fit-base-scenario.sh): the field scenario on 15 m, clean.
source "$root/scripts/fit-base-scenario.sh"
# Two cases run at a time (FIT_PROOF_JOBS), planter-fit with one thread each: the clamp's
# channel dominates a fit, so two cases keep both cores busy. Each case writes its result line
# to OUT/NAME.line and says it on stderr as it finishes (the whole proof takes minutes); the
# lines are printed again in order at the end, with the count.
jobs_max=${FIT_PROOF_JOBS:-2}
names=()
spawn() {  # spawn WORKER NAME ARGS...
  local name=$2
  # FIT_PROOF_ONLY=REGEX runs the cases whose names match (while working on one class).
  [[ -z ${FIT_PROOF_ONLY:-} || $name =~ $FIT_PROOF_ONLY ]] || return 0
  names+=("$name")
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n; done
  {
    "$@" >"$out/$name.line" 2>&1
    echo "fit-proof: $(head -n 1 "$out/$name.line")" >&2
  } &
}
judge() {  # judge NAME EXPECT: prints the case's line from its fit.json
  /usr/bin/python3 "$root/scripts/fit_proof_check.py" "$out/$1-fit/fit.json" "$1" "$2" \
    "$out/$1.coverage" "$out/$1/recording.csv"
}
# planter-fit on one core, its user and system CPU kept in OUT/NAME-fit.cpu: scripts/fit-cpu.sh
# reads them rather than fitting each recording again (the proof is the sample of recordings).
fit_case() {  # fit_case NAME RECORDING
  /usr/bin/time -f "%U %S" -o "$out/$1-fit.cpu" \
    "$fit" "$2" --out "$out/$1-fit" --json --jobs 1 >"$out/$1-fit.stdout" 2>&1
}
sim_case() {  # sim_case NAME NOISE EXPECT [--base-sed SED_EXPR] [--drop COLUMN] [effects lines...]
  local name=$1 noise=$2 expect=$3 base_sed="" drop=""
  shift 3
  if [ "${1:-}" = --base-sed ]; then
    base_sed=$2
    shift 2
  fi
  if [ "${1:-}" = --drop ]; then
    drop=$2
    shift 2
  fi
  # The effect keys go at the end, under [effects] (the base's last table). The fit's outputs go
  # beside the run's folder, not in it: a run's folder holds only what the run wrote.
  { base "$noise" | sed -e "$base_sed"; printf '%s\n' "$@"; } >"$out/$name.toml"
  "$sim" run "$out/$name.toml" --out "$out/$name" >/dev/null 2>"$out/$name.sim.err" || {
    echo "FAIL $name: planter-sim failed: $(head -1 "$out/$name.sim.err")"
    return
  }
  local recording=$out/$name/recording.csv
  if [ -n "$drop" ]; then
    # As a field log without those sensors: the columns left out, beside the run's folder.
    local -a dropped
    read -ra dropped <<<"$drop"
    recording=$out/$name-field-log.csv
    /usr/bin/python3 "$root/scripts/drop-columns.py" "$out/$name/recording.csv" "$recording" "${dropped[@]}"
    echo "$drop" >"$out/$name.drop"  # for scripts/fit-cpu.sh's longer runs of this case
  fi
  fit_case "$name" "$recording"
  judge "$name" "$expect"
}
run_case() { spawn sim_case "$@"; }
for noise in 0.5 2.0 5.0; do
  run_case "clean-noise-$noise" "$noise" clean
done
run_case relaxation 1.0 "clamp_force:viscoelastic relaxation (creep) of the clamp:fraction=0.3,tau_s=3" \
  "clamp_relaxation_frac = 0.3" "clamp_relaxation_tau_s = 3.0"
# Two time scales (a Prony series of two terms): half the drop in a second, the rest over 40 s.
for noise in 0.5 2.0; do
  run_case "relaxation-two-scales-noise-$noise" "$noise" \
    "clamp_force:viscoelastic relaxation (creep) of the clamp:fraction=0.2,tau_s=1;clamp_force:viscoelastic relaxation, a second time scale (Prony series):fraction2=0.2,tau2_s=40" \
    "clamp_relaxation_frac = 0.2" "clamp_relaxation_tau_s = 1.0" \
    "clamp_relaxation2_frac = 0.2" "clamp_relaxation2_tau_s = 40.0"
done
run_case force-offset 1.0 "clamp_force:sensor offset:offset=8" "force_offset_N = 8.0"
run_case force-drift 1.0 "clamp_force:sensor drift:drift_per_s=0.05" "force_drift_N_per_min = 3.0"
run_case vibration 1.0 "clamp_force:periodic disturbance (vibration):amplitude=6,frequency_hz=7" \
  "vibration_hz = 7.0" "vibration_force_N = 6.0"
# Above the analysed rate (the recording is decimated about 3:1): removed before decimation,
# found at the recording's own rate, at two noise levels.
for noise in 0.5 2.0; do
  run_case "vibration-fast-noise-$noise" "$noise" \
    "clamp_force:periodic disturbance (vibration):amplitude=6,frequency_hz=38" \
    "vibration_hz = 38.0" "vibration_force_N = 6.0"
done
run_case disc-coulomb 1.0 "disc_torque:Coulomb friction:coulomb=2" "disc_coulomb_Nm = 2.0"
run_case disc-stribeck 1.0 "disc_torque:Stribeck friction:stribeck_extra=3,stribeck_speed=0.05" \
  "disc_stribeck_Nm = 3.0" "disc_stribeck_radps = 0.05"
run_case disc-dead-zone 1.0 "omega:dead zone:width=0.1" "disc_deadzone_radps = 0.1"
run_case command-delay 1.0 "omega:transport delay:delay_s=0.3" "command_delay_s = 0.3"
run_case slip-with-draft 1.0 "v_wheel:wheel slip growing with draft load:slip_per_kN=0.05" \
  "slip_per_kN = 5.0"
# The soil wheel is larger than the board was calibrated for: 0.162 m against 0.15464 m.
run_case wheel-radius 1.0 "v_wheel:wrong effective wheel radius:radius_error=-0.04546" \
  --base-sed "s|^wheel_radius_m = .*|wheel_radius_m = 0.162|"
run_case depth-sag 1.0 "depth_mm:actuator compliance (sag) under load:sag_per_kN=8" \
  "depth_sag_mm_per_kN = 8.0"
run_case pair-relaxation-delay 1.0 \
  "clamp_force:viscoelastic relaxation (creep) of the clamp:fraction=0.3;omega:transport delay:delay_s=0.15" \
  "clamp_relaxation_frac = 0.3" "clamp_relaxation_tau_s = 3.0" "command_delay_s = 0.15"
run_case pair-offset-vibration 1.0 \
  "clamp_force:sensor offset:offset=8;clamp_force:periodic disturbance (vibration):amplitude=6,frequency_hz=7" \
  "force_offset_N = 8.0" "vibration_hz = 7.0" "vibration_force_N = 6.0"
# A parameter that changes once, midway (287 s recordings): the clamp stiffens by 40 % (a new
# seedling batch), the soil's draft grows by half; at two noise levels on the load cell.
for noise in 0.5 2.0; do
  run_case "clamp-stiffer-noise-$noise" "$noise" "clamp_force:change:k_c=1.4@143" \
    "change_at_s = 143.0" "clamp_stiffness_change_pct = 40.0"
done
run_case soil-heavier 1.0 "depth_force:change:draft_100mm=1.5@143" \
  "change_at_s = 143.0" "soil_draft_change_pct = 50.0"
# Terrain the depth wheel follows is no effect of the library: in a field log without a
# terrain measurement (known_terrain_depth_mm left out) it must be reported as an unexplained
# residual on depth_mm, not forced onto a wrong name.
# Field logs (issue 52): what the scenario varies on purpose, without its known_* columns (and
# without the truth columns a real machine cannot have), is named as disturbances along the row,
# each with the dropped column's size. The terrain alone; then terrain, slip and stems together.
# What the field scenario varies on purpose (terrain, the slip along the row, stems of every
# diameter), and the three disturbances a field log of it names.
field_sed="s|^roughness_mm = .*|roughness_mm = 6.0|; s|^slip_variation_pct = .*|slip_variation_pct = 1.0|; s|^diameter_min_mm = .*|diameter_min_mm = 8.3|; s|^diameter_max_mm = .*|diameter_max_mm = 11.4|"
field_disturbances="v_wheel:disturbance:known_slip*100;clamp_force:disturbance:known_nip_mm;depth_mm:disturbance:known_terrain_depth_mm"
run_case terrain 1.0 "depth_mm:disturbance:known_terrain_depth_mm" \
  --base-sed "s|^roughness_mm = .*|roughness_mm = 6.0|" --drop known_terrain_depth_mm
run_case field-log 1.0 "$field_disturbances" --base-sed "$field_sed" --drop "known_* true_*"
# The same field over 36 m, about ten and a half minutes. With that much of the row, effects
# chosen before the stems' spread read it as a play and a hysteresis: the force loop moves the
# roller with each stem, so the roller's history carries them.
run_case field-log-36m 1.0 "$field_disturbances" --base-sed "$field_sed; s|^distance_m = .*|distance_m = 36.0|" \
  --drop "known_* true_*"
# The same field log with the clamp's relaxation hidden: named beside the disturbances, the
# stems' spread among them.
run_case field-log-relaxation 1.0 \
  "clamp_force:viscoelastic relaxation (creep) of the clamp:fraction=0.3,tau_s=3;$field_disturbances" \
  --base-sed "$field_sed" \
  --drop "known_* true_*" "clamp_relaxation_frac = 0.3" "clamp_relaxation_tau_s = 3.0"
# Nothing hidden, and everything the field scenario varies on purpose put back (terrain, the
# slip's variation along the row, seedlings of every diameter in the nip), carried in the
# recording as known disturbances: clean on every channel (issue 32, item 2).
run_case clean-with-known-disturbances 1.0 clean --base-sed "$field_sed"
# A second generator, written apart from planter-sim (scripts/outside_machine.py): no firmware,
# an open-loop operator, Runge-Kutta at 1 ms, jittered 100 Hz sampling, its own machine values.
outside_case() {  # outside_case NAME EXPECT [outside_machine.py options...]
  local name=$1 expect=$2
  shift 2
  mkdir -p "$out/$name"
  /usr/bin/python3 "$root/scripts/outside_machine.py" "$out/$name/recording.csv" "$@" || {
    echo "FAIL $name: the outside generator failed"
    return
  }
  fit_case "$name" "$out/$name/recording.csv"
  judge "$name" "$expect"
}
run_outside() { spawn outside_case "$@"; }
for noise in 1 4; do
  run_outside "outside-clean-noise-$noise" clean --noise $noise --seed 11
  run_outside "outside-relaxation-noise-$noise" \
    "clamp_force:viscoelastic relaxation (creep) of the clamp:fraction=0.3,tau_s=2" \
    --noise $noise --seed 12 --relaxation 0.3 2.0
done
# Hysteresis of the clamp (Bouc-Wen, 6 N over 0.5 mm); its height is checked, its shape delta
# is printed in fit.json (0.49 mm for 0.5 on the seed below).
for noise in 1 4; do
  run_outside "outside-hysteresis-noise-$noise" \
    "clamp_force:hysteresis of the clamp (Bouc-Wen):height=6" \
    --noise $noise --seed 18 --hysteresis 6 0.5
done
run_outside outside-command-delay "omega:transport delay:delay_s=0.2" --seed 13 --command-delay 0.2
run_outside outside-coulomb "disc_torque:Coulomb friction:coulomb=1" --seed 14 --coulomb 1.0
run_outside outside-force-offset "clamp_force:sensor offset:offset=5" --seed 15 --force-offset 5
run_outside outside-vibration-fast \
  "clamp_force:periodic disturbance (vibration):amplitude=3,frequency_hz=30" \
  --seed 16 --vibration 30 3
# Wider (issue 32, item 6): machines drawn across the generator's ranges (DRAWN in
# outside_machine.py), one with a draft that is there in full while moving and gone at rest; a
# play of 6 mm behind the depth actuator, powered up against either end of its gap; a clamp
# hysteresis of 1 N on a quiet load cell and of 20 kN on a press 200 times stiffer.
run_outside outside-drawn-1-instant-draft clean --seed 22 --draw-nominal 1 --instant-draft
run_outside outside-drawn-2 clean --seed 26 --draw-nominal 2
for end in low high; do
  run_outside "outside-play-from-$end" "depth_mm:backlash (play) after the drive:gap=6" \
    --seed 21 --depth-play 6 $end
done
run_outside outside-hysteresis-1N "clamp_force:hysteresis of the clamp (Bouc-Wen):height=1" \
  --seed 24 --noise 0.25 --hysteresis 1 0.5
# What outside trials found (issue 52): a noisy ground speed sensor (an input's noise, not the
# output's to explain), a clamp 40 % stiffer from 150 s, a load cell that reads no more than
# 60 N, a disc speed logged in 0.02 rad/s steps, and a log of a speed loop alone (a clean
# first-order system).
run_outside outside-noisy-ground clean --seed 31 --ground-noise 0.002
run_outside outside-clamp-stiffer "clamp_force:change:k_c=1.4@150" --seed 31 --stiffer-at 150 1.4
run_outside outside-force-limit "clamp_force:hard limit of the output (saturation):limit=60" \
  --seed 31 --force-limit 60
run_outside outside-omega-steps "omega:steps:step=0.02" --seed 31 --omega-step 0.02
run_outside outside-first-order clean --seed 32 --disc-only
run_outside outside-hysteresis-20kN "clamp_force:hysteresis of the clamp (Bouc-Wen):height=20000" \
  --seed 23 --clamp-scale 200 --hysteresis 20000 0.5
wait
passed=0
exact=0
for name in "${names[@]}"; do
  line=$(cat "$out/$name.line")
  echo "$line"
  if [[ $line == PASS* ]]; then
    passed=$((passed + 1))
    [[ $line == *"also named"* ]] || exact=$((exact + 1))
  fi
done
total=${#names[@]}
echo "of the $passed that pass, $exact name nothing beyond what was hidden"
# Whether the stated uncertainty is as sure as it is right (issue 32, item 5): the hidden value
# inside the stated 95 % interval should be about 95 % of the statistical parameters.
for kind in statistical grid; do
  covered=0
  checked=0
  for name in "${names[@]}"; do
    [ -s "$out/$name.coverage" ] || continue
    covered=$((covered + $(grep -c "^covered $kind " "$out/$name.coverage" || true)))
    checked=$((checked + $(grep -c " $kind " "$out/$name.coverage" || true)))
  done
  if [ "$kind" = statistical ]; then
    echo "stated 95 % intervals (+-1.96 SD) holding the hidden value: $covered of $checked parameters"
    # How far that count is from 95 %, in its own terms: the binomial chance of a count as low.
    if [ "$checked" -gt 0 ]; then
      chance=$(/usr/bin/python3 -c 'import math, sys
n, k = int(sys.argv[1]), int(sys.argv[2])
print("%.0f" % (100 * sum(math.comb(n, i) * 0.95**i * 0.05**(n - i) for i in range(k + 1))))' \
        "$checked" "$covered")
      echo "  (intervals right 95 % of the time hold $covered or fewer of $checked in $chance % of proofs)"
    fi
  else
    echo "grid parameters within their stated resolution of the hidden value: $covered of $checked"
  fi
done
# The misses of this run's cases (OUT_DIR may hold other cases' files from an earlier run).
for name in "${names[@]}"; do
  [ -s "$out/$name.coverage" ] && grep -h "^missed statistical" "$out/$name.coverage" | sed 's/^/  /'
done
# What outside trials found (issue 52), apart: field logs without their known disturbances
# (one over 36 m, one with a relaxation hidden beside them), a noisy input, a changed clamp, a
# hard limit, a coarse log and a first-order loop alone.
field_passed=0
field_total=0
for name in "${names[@]}"; do
  case $name in
    terrain | field-log | field-log-36m | field-log-relaxation | outside-noisy-ground | outside-clamp-stiffer | outside-force-limit | \
      outside-omega-steps | outside-first-order) ;;
    *) continue ;;
  esac
  field_total=$((field_total + 1))
  [[ $(cat "$out/$name.line") == PASS* ]] && field_passed=$((field_passed + 1))
done
echo "of them, field logs and outside findings: $field_passed of $field_total pass"
echo "planter-fit blind proof: $passed of $total cases pass"
