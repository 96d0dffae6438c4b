#!/usr/bin/env bash
# planter-dem's bad input: one clear message naming file, line and key, and exit code 2.
set -uo pipefail
tool=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
expect() {  # expect CODE PATTERN -- ARGS...
  local code=$1 pattern=$2
  shift 3
  local out rc
  out=$("$tool" "$@" 2>&1 >/dev/null)
  rc=$?
  if [ "$rc" -ne "$code" ] || ! grep -q -- "$pattern" <<<"$out"; then
    echo "FAIL: planter-dem $* -> exit $rc, '$out' (wanted $code and /$pattern/)"
    fails=$((fails + 1))
  fi
}
printf '[bond]\nnormal_stiffness_N_m3 = 4.8e9\nradius_mm = 40\n' >"$work/range.toml"
expect 2 "range.toml:3: 'bond.radius_mm'" -- compress --params "$work/range.toml" --out "$work/o"
printf '[bond]\nstiffnes = 1\n' >"$work/typo.toml"
expect 2 "typo.toml:2: 'bond.stiffnes'" -- compress --params "$work/typo.toml" --out "$work/o"
printf '[bond\n' >"$work/syntax.toml"
expect 2 "syntax.toml:1" -- compress --params "$work/syntax.toml" --out "$work/o"
printf '[test]\nstroke_mm = 12\n' >"$work/stroke.toml"
expect 2 "stroke_mm" -- compress --params "$work/stroke.toml" --out "$work/o"
expect 2 "out" -- compress
expect 2 "speedup" -- compress --out "$work/o" --speedup 0
expect 2 "jobs" -- calibrate --out "$work/o" --jobs 0
expect 2 "threads" -- compress --out "$work/o" --threads 0
expect 2 "diameters" -- reduce --out "$work/o" --diameters-mm 8.3,abc
# A calibration stage's plan (what a Slurm task runs): a missing plan, another file, an index
# the plan has not.
expect 2 "nothing.json: no such file" -- plan-run "$work/nothing.json" 0
printf '{"keys": 3}\n' >"$work/other.json"
expect 2 "other.json: not a plan of planter-dem's calibration" -- plan-run "$work/other.json" 0
printf '{"planter-dem calibration stage": 1, "runs_dir": "%s", "keys": ["abc"]}\n' "$work" \
  >"$work/plan.json"
expect 2 "no run 4 (the plan has 1, from 0)" -- plan-run "$work/plan.json" 4
expect 2 "abc.toml: no such file" -- plan-run "$work/plan.json" 0
expect 2 "executor" -- calibrate --out "$work/o" --executor cloud
# An empty parameter file is refused (it would run the defaults under the file's name), and a
# run whose cost is hours is refused before it starts, with the estimate.
: >"$work/empty.toml"
expect 2 "empty.toml:1: holds no parameters" -- compress --params "$work/empty.toml" --out "$work/o"
printf '[test]\ntime_step_s = 1e-8\n' >"$work/tiny_step.toml"
expect 2 "one compression would take 3600000 steps" -- compress --params "$work/tiny_step.toml" --out "$work/o"
# Issue 28, item 14: a valid file of fine particles ran 300 s at 1 GB without a word; the
# particles count in the cost, before any memory is taken.
printf '[seedling]\nlength_mm = 400\ndiameter_mm = 30\nparticle_radius_mm = 0.3\nlayers = 4\n' >"$work/fine.toml"
expect 2 "one compression would take 3[0-9]* particles x 18000 steps" -- compress --params "$work/fine.toml" --out "$work/o"
mkfifo "$work/fifo.toml"
expect 2 "fifo.toml: is a FIFO, not a regular file" -- compress --params "$work/fifo.toml" --out "$work/o"
[ -e "$work/o" ] && { echo "FAIL: refused runs left $work/o"; fails=$((fails + 1)); }
# The README's compress on one thread and on two: the same curve, bit for bit (a step's threads
# share its pairs and particles, never the order of a sum).
for t in 1 2; do
  "$tool" compress --speedup 200 --threads "$t" --out "$work/threads-$t" >/dev/null ||
    { echo "FAIL: planter-dem compress --threads $t exited $?"; fails=$((fails + 1)); }
done
cmp -s "$work/threads-1/curve.csv" "$work/threads-2/curve.csv" ||
  { echo "FAIL: curve.csv differs between --threads 1 and 2"; fails=$((fails + 1)); }
[ "$fails" -eq 0 ] && echo "planter-dem bad input: all rejected with exit 2 and a message; --threads changes no bit"
exit "$fails"
