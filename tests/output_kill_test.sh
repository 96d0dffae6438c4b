#!/usr/bin/env bash
# kill -9 at five points of each tool that writes outputs: the output directory (or file) must
# hold the old set or the new set, whole, never a mix, and the next run must still work.
# A set is whole when run.json lists exactly the files present, each of the listed size.
# Usage: output_kill_test.sh PLANTER_SIM PLANTER_FIT PLANTER_DEM PLANTER_CAN SOURCE_DIR
set -uo pipefail
sim=$1 fit=$2 dem=$3 can=$4 src=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails=0
say_fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# Prints a digest of the set in DIR, or fails when the set is not whole.
set_digest() {
  local dir=$1
  [ -f "$dir/run.json" ] || { echo "no run.json"; return 1; }
  python3 - "$dir" <<'EOF'
import hashlib, json, os, sys
d = sys.argv[1]
m = json.load(open(os.path.join(d, "run.json")))
present = sorted(f for f in os.listdir(d) if f != "run.json")
if present != sorted(m["files"]):
    print("files %s but run.json lists %s" % (present, sorted(m["files"]))); sys.exit(1)
h = hashlib.sha256()
for f in present:
    p = os.path.join(d, f)
    if os.path.getsize(p) != m["files"][f]:
        print("%s is %d bytes, run.json says %d" % (f, os.path.getsize(p), m["files"][f])); sys.exit(1)
    h.update(f.encode()); h.update(open(p, "rb").read())
print(h.hexdigest())
EOF
}

# kill_points NAME OUT -- COMMAND...: a complete run first (the old set), then five runs of the
# same command killed at 10, 30, 50, 75 and 95 % of the complete run's time, each checked.
kill_points() {
  local name=$1 out=$2
  shift 3
  local t0 t1 elapsed old now killed=0
  t0=$(date +%s%N)
  "$@" >/dev/null 2>&1 || { say_fail "$name: the complete run failed"; return; }
  t1=$(date +%s%N)
  elapsed=$(((t1 - t0) / 1000000))
  old=$(set_digest "$out") || { say_fail "$name: the complete run's set is not whole: $old"; return; }
  for pct in 10 30 50 75 95; do
    "$@" >/dev/null 2>&1 &
    local pid=$!
    sleep "$(awk -v ms="$elapsed" -v p="$pct" 'BEGIN { printf "%.3f", ms * p / 100000 }')"
    if kill -9 "$pid" 2>/dev/null; then killed=$((killed + 1)); fi
    wait "$pid" 2>/dev/null
    now=$(set_digest "$out") || { say_fail "$name: killed at $pct %: not a whole set: $now"; continue; }
    old=$now  # the old set, or a finished new one: either is the set the next kill must keep
  done
  # The next run cleans what the killed runs left and writes a whole set.
  "$@" >/dev/null 2>&1 || say_fail "$name: the run after the kills failed"
  set_digest "$out" >/dev/null || say_fail "$name: the run after the kills left no whole set"
  if compgen -G "$out.partial-*" >/dev/null; then say_fail "$name: staging left: $(ls -d "$out".partial-*)"; fi
  echo "$name: $killed of 5 runs killed mid-way (complete run $elapsed ms); every set whole"
}

sed "s|\.\./boards|$src/boards|; s|\.\./models|$src/models|; s|^distance_m = .*|distance_m = 2.0|" \
  "$src/scenarios/zhangqiu-field.toml" | sed "s|^stops = .*|stops = []|" >"$work/s.toml"
kill_points planter-sim "$work/sim" -- "$sim" run "$work/s.toml" --quiet --out "$work/sim"
# A small recording of the disc drive alone keeps the fit to about a second.
python3 - "$work/drive.csv" <<'EOF'
import math, sys
with open(sys.argv[1], "w") as f:
    f.write("t,omega_cmd,omega\n")
    w = 0.0
    for k in range(1000):
        cmd = 0.3 if (k // 200) % 2 == 0 else 0.1
        w += (cmd - w) * 0.05
        f.write("%.2f,%.4f,%.5f\n" % (k * 0.01, cmd, w + 0.002 * math.sin(k * 1.7)))
EOF
kill_points planter-fit "$work/fit" -- "$fit" "$work/drive.csv" --jobs 1 --out "$work/fit"
# The calibrated seedling, 24 mm long, at 500x the platen speed and a 10 us step: the physics
# is not what this test checks, and the runs stay at seconds under the sanitizers.
{ cat "$src/models/seedling_dem.toml"; printf '\n[seedling]\nlength_mm = 24\n'; } |
  sed 's|^\[test\]|[test]\ntime_step_s = 1e-5|' >"$work/short.toml"
kill_points "planter-dem compress" "$work/dem" -- "$dem" compress --params "$work/short.toml" \
  --speedup 500 --out "$work/dem"
kill_points "planter-dem reduce" "$work/red" -- "$dem" reduce --params "$work/short.toml" \
  --speedup 500 --diameters-mm 9.3 --jobs 1 --out "$work/red"

# planter-can decode -o writes one file: the old content or the new, whole.
printf '(1.000000) can0 080#\n(1.010000) can0 080#\n' >"$work/small.log"
"$can" --board "$src/boards/host-sim/board.toml" decode "$work/small.log" -o "$work/d.csv" >/dev/null
old=$(sha256sum <"$work/d.csv")
python3 - "$work/big.log" <<'EOF'
import sys
with open(sys.argv[1], "w") as f:
    for k in range(200000):
        t = 1.0 + k * 0.01
        f.write("(%.6f) can0 080#\n(%.6f) can0 182#0700E8030000\n" % (t, t + 0.001))
EOF
"$can" --board "$src/boards/host-sim/board.toml" decode "$work/big.log" -o "$work/whole.csv" >/dev/null
new=$(sha256sum <"$work/whole.csv")
for pct in 1 2 3 4 5; do
  "$can" --board "$src/boards/host-sim/board.toml" decode "$work/big.log" -o "$work/d.csv" >/dev/null 2>&1 &
  pid=$!
  sleep "0.$pct"
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  now=$(sha256sum <"$work/d.csv")
  if [ "$now" != "$old" ] && [ "$now" != "$new" ]; then
    say_fail "decode -o: killed at 0.$pct s: d.csv is neither the old file nor the whole new one"
  fi
done
echo "planter-can decode -o: 5 kills, the CSV always whole"
[ "$fails" -eq 0 ] && echo "outputs under kill -9: always the old set or the new set"
exit "$fails"
