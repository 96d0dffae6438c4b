#!/usr/bin/env bash
# planter-fit's CPU time per recording, as distributions (issue 52, item 4: under 30 s of CPU
# on one core for any 10-minute recording). Every fit runs with --jobs 1, two at a time (a
# process's CPU time is its own). Two samples:
# - as recorded: every recording a blind proof left (scripts/fit-proof.sh BUILD OUT: the proof's
#   own cases, the outside generator's and the field logs, 4.8-5 min), and the field scenario's
#   own run as a field log (8.6 min). A recording whose fit the proof timed (OUT/NAME-fit.cpu)
#   is read, not fitted again; the others (a proof left by an older script) are fitted here,
#   every EVERY-th of them;
# - 10 minutes: every EVERY-th of the proof's planter-sim cases (OUT/NAME.toml), run again over
#   2.4 times its row and cut to its first 10 minutes (60,000 rows at 100 Hz), without the
#   columns the proof dropped from it (OUT/NAME.drop); and every EVERY-th of the outside
#   generator's recordings twice, end to end (its operator is scripted over its 5 minutes).
# Prints one line per recording, then each distribution, and last the count of 10-minute
# recordings within 30 s.
# Usage: scripts/fit-cpu.sh BUILD_DIR PROOF_OUT_DIR [EVERY]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:?usage: fit-cpu.sh BUILD_DIR PROOF_OUT_DIR [EVERY]}
proof=${2:?usage: fit-cpu.sh BUILD_DIR PROOF_OUT_DIR [EVERY]}
every=${3:-1}
fit=$build/apps/planter-fit/planter-fit
sim=$build/apps/planter-sim/planter-sim
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$sim" run "$root/scenarios/zhangqiu-field.toml" --out "$work/field" --quiet >/dev/null
/usr/bin/python3 "$root/scripts/drop-columns.py" "$work/field/recording.csv" "$work/field-log.csv" \
  'known_*' 'true_*'

# timed_by_proof RECORDING: the file holding the proof's own timing of its fit.
timed_by_proof() {
  local name=${1#"$proof"/}
  name=${name%/recording.csv}
  echo "$proof/${name%-field-log.csv}-fit.cpu"
}
# ten_minutes NAME: the proof's case NAME run over a longer row, its first 10 minutes in
# $work/ten-NAME.csv.
ten_minutes() {
  local name=$1 run=$work/ten-$1
  /usr/bin/python3 - "$proof/$name.toml" "$run.toml" <<'EOF'
import re, sys
text = open(sys.argv[1]).read()
m = re.search(r"^distance_m = ([0-9.]+)", text, re.M)
if not m:
    sys.exit("fit-cpu: no distance_m in %s" % sys.argv[1])
text = text[:m.start()] + "distance_m = %.2f" % (2.4 * float(m.group(1))) + text[m.end():]
open(sys.argv[2], "w").write(text)
EOF
  "$sim" run "$run.toml" --out "$run" --quiet >/dev/null
  local recording=$run/recording.csv
  if [ -s "$proof/$name.drop" ]; then
    local -a dropped
    read -ra dropped <"$proof/$name.drop"
    /usr/bin/python3 "$root/scripts/drop-columns.py" "$recording" "$run-log.csv" "${dropped[@]}"
    recording=$run-log.csv
  fi
  /usr/bin/python3 "$root/scripts/long_recording.py" "$run.csv" 1 60000 "$recording"
  rm -rf "$run" "$run-log.csv"
}

# twice NAME: the outside generator's recording NAME twice, end to end, in $work/ten-NAME.csv.
twice() {
  local r=$proof/$1/recording.csv
  /usr/bin/python3 "$root/scripts/long_recording.py" "$work/ten-$1.csv" 2 \
    "$(($(grep -vc '^#' "$r") - 1))" "$r"
}

# Each recording with its group and the name its line shows.
recordings=("$work/field-log.csv")
groups=(recorded)
names=(field-log.csv)
i=0
for r in "$proof"/*/recording.csv "$proof"/*-field-log.csv; do
  [ -f "$r" ] || continue
  # A case the proof fitted as a field log was timed on that log, not on its full recording.
  [ -f "${r%/recording.csv}-field-log.csv" ] && continue
  if [ -s "$(timed_by_proof "$r")" ] || [ $((i++ % every)) -eq 0 ]; then
    recordings+=("$r") groups+=(recorded) names+=("${r#"$proof"/}")
  fi
done
[ ${#recordings[@]} -gt 1 ] || { echo "fit-cpu: no recordings under $proof (run scripts/fit-proof.sh first)" >&2; exit 2; }
i=0
for toml in "$proof"/*.toml; do
  [ -f "$toml" ] || continue
  if [ $((i++ % every)) -eq 0 ]; then
    name=$(basename "$toml" .toml)
    ten_minutes "$name"
    recordings+=("$work/ten-$name.csv") groups+=(10min) names+=("$name (run again over 10 min)")
  fi
done
i=0
for r in "$proof"/*/recording.csv; do
  name=$(basename "$(dirname "$r")")
  [ -f "$proof/$name.toml" ] && continue  # a planter-sim case, run again above
  if [ $((i++ % every)) -eq 0 ]; then
    twice "$name"
    recordings+=("$work/ten-$name.csv") groups+=(10min) names+=("$name (twice, end to end)")
  fi
done

one() {  # one INDEX GROUP RECORDING NAME: its line into $work/INDEX.line
  local n=$1 group=$2 r=$3 name=$4 user sys timed
  timed=$(timed_by_proof "$r")
  if [ "${r#"$proof"/}" != "$r" ] && [ -s "$timed" ]; then
    # time(1) puts "Command exited with non-zero status" (or "terminated by signal") before its
    # figures when the fit failed: that is a failed fit, as below, not a CPU time.
    if grep -q '^Command ' "$timed"; then
      echo "fit-cpu: planter-fit failed on $r in the proof ($(head -n 1 "$timed"))" >&2
      return 1
    fi
    read -r user sys <"$timed"
  else
    /usr/bin/time -f "%U %S" -o "$work/$n.time" "$fit" "$r" --out "$work/fit-$n" --jobs 1 --force \
      >/dev/null || { echo "fit-cpu: planter-fit failed on $r" >&2; return 1; }
    read -r user sys <"$work/$n.time"
    rm -rf "$work/fit-$n"
  fi
  /usr/bin/python3 -c 'import sys
cpu, group, path, name = float(sys.argv[1]) + float(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
t = [float(l.split(",")[0]) for l in open(path) if l[:1].isdigit()]
print("%-8s %6.1f s CPU for %4.1f min  %s" % (group, cpu, (t[-1] - t[0]) / 60.0, name))' \
    "$user" "$sys" "$group" "$r" "$name" >"$work/$n.line"
}
for n in "${!recordings[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge 2 ]; do wait -n; done
  one "$n" "${groups[$n]}" "${recordings[$n]}" "${names[$n]}" &
done
wait
for n in "${!recordings[@]}"; do
  [ -s "$work/$n.line" ] || { echo "fit-cpu: no time for ${recordings[$n]}" >&2; exit 1; }
  cat "$work/$n.line"
done | tee "$work/all.lines"
/usr/bin/python3 - "$work/all.lines" <<'EOF'
import re, sys
cpu, minutes = {}, {}
for line in open(sys.argv[1]):
    m = re.match(r"^(\S+)\s+([0-9.]+) s CPU for\s+([0-9.]+) min", line)
    if m:
        cpu.setdefault(m.group(1), []).append(float(m.group(2)))
        minutes.setdefault(m.group(1), []).append(float(m.group(3)))
def spread(v):
    v = sorted(v)
    q = lambda p: v[min(len(v) - 1, int(p * (len(v) - 1) + 0.5))]
    return "min %.1f, median %.1f, 90 %% %.1f, max %.1f" % (v[0], q(0.5), q(0.9), v[-1])
for group, label in (("recorded", "as recorded"), ("10min", "10-minute recordings")):
    c, m = cpu.get(group, []), minutes.get(group, [])
    if not c:
        sys.exit("fit-cpu: no %s" % label)
    print("CPU s, %s (%.1f-%.1f min), %d: %s; %d within 30 s"
          % (label, min(m), max(m), len(c), spread(c), sum(x <= 30.0 for x in c)))
short = [x for x in minutes["10min"] if x < 9.95]
if short:
    sys.exit("fit-cpu: %d of the 10-minute recordings are shorter (%.2f min)" % (len(short), min(short)))
c = cpu["10min"]
print("planter-fit CPU per 10-minute recording, one core: %d of %d within 30 s (max %.1f s)"
      % (sum(x <= 30.0 for x in c), len(c), max(c)))
EOF
