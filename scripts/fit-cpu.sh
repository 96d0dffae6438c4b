#!/usr/bin/env bash
# planter-fit's CPU time per recording, as a distribution (issue 52, item 4: under 30 s of CPU
# on one core for any 10-minute recording). Runs planter-fit with --jobs 1 on every recording a
# blind proof left (scripts/fit-proof.sh BUILD OUT: the proof's own cases, the outside
# generator's and the field logs), and on the field scenario's own run as a field log, timing
# user + system CPU of each, scaled to 10 minutes of recording. Prints one line per recording,
# then the distribution, and last the count within 30 s.
# Usage: scripts/fit-cpu.sh BUILD_DIR PROOF_OUT_DIR [EVERY]
# A recording whose fit the proof timed (OUT/NAME-fit.cpu, written by scripts/fit-proof.sh) is
# read, not fitted again: the proof ran it with --jobs 1, two at a time, and a process's CPU time
# is its own. The others (a proof left by an older script) are fitted here, two at a time; of
# those, EVERY=K takes every K-th (1: all).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:?usage: fit-cpu.sh BUILD_DIR PROOF_OUT_DIR}
proof=${2:?usage: fit-cpu.sh BUILD_DIR PROOF_OUT_DIR}
fit=$build/apps/planter-fit/planter-fit
sim=$build/apps/planter-sim/planter-sim
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$sim" run "$root/scenarios/zhangqiu-field.toml" --out "$work/field" --quiet >/dev/null
/usr/bin/python3 "$root/scripts/drop-columns.py" "$work/field/recording.csv" "$work/field-log.csv" \
  'known_*' 'true_*'
every=${3:-1}
recordings=("$work/field-log.csv")
i=0
# timed_by_proof RECORDING: the file holding the proof's own timing of its fit, if there is one.
timed_by_proof() {
  local name=${1#"$proof"/}
  name=${name%/recording.csv}
  echo "$proof/${name%-field-log.csv}-fit.cpu"
}
for r in "$proof"/*/recording.csv "$proof"/*-field-log.csv; do
  [ -f "$r" ] || continue
  if [ -s "$(timed_by_proof "$r")" ]; then
    recordings+=("$r")
  else
    [ $((i % every)) -eq 0 ] && recordings+=("$r")
    i=$((i + 1))
  fi
done
[ ${#recordings[@]} -gt 1 ] || { echo "fit-cpu: no recordings under $proof (run scripts/fit-proof.sh first)" >&2; exit 2; }
one() {  # one INDEX RECORDING: its line into $work/INDEX.line
  local n=$1 r=$2 user sys minutes timed
  timed=$(timed_by_proof "$r")
  if [ "$r" != "$work/field-log.csv" ] && [ -s "$timed" ]; then
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
  fi
  minutes=$(/usr/bin/python3 -c 'import sys
t = [float(l.split(",")[0]) for l in open(sys.argv[1]) if l[:1].isdigit()]
print((t[-1] - t[0]) / 60.0)' "$r")
  /usr/bin/python3 -c 'import sys
cpu, minutes, name = float(sys.argv[1]) + float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
print("%8.1f s CPU per 10 min  (%5.1f s for %4.1f min)  %s" % (cpu * 10.0 / max(minutes, 1e-9), cpu, minutes, name))' \
    "$user" "$sys" "$minutes" "${r#"$proof"/}" >"$work/$n.line"
}
for n in "${!recordings[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge 2 ]; do wait -n; done
  one "$n" "${recordings[$n]}" &
done
wait
for n in "${!recordings[@]}"; do
  [ -s "$work/$n.line" ] || { echo "fit-cpu: no time for ${recordings[$n]}" >&2; exit 1; }
  cat "$work/$n.line"
done
# Two figures: the CPU each recording took as it is (its length printed), and scaled to 10
# minutes in proportion, an upper bound (the analysis thins any recording to 12,000 rows, so a
# longer one costs less than in proportion; the full-rate refinements cost in proportion).
cat "$work"/*.line | /usr/bin/python3 -c '
import re, sys
raw, per10, minutes = [], [], []
for line in sys.stdin:
    m = re.search(r"^\s*([0-9.]+) s CPU per 10 min\s+\(\s*([0-9.]+) s for\s+([0-9.]+) min\)", line)
    if m:
        per10.append(float(m.group(1))); raw.append(float(m.group(2))); minutes.append(float(m.group(3)))
def spread(v):
    v = sorted(v)
    q = lambda p: v[min(len(v) - 1, int(p * (len(v) - 1) + 0.5))]
    return "min %.1f, median %.1f, 90 %% %.1f, max %.1f" % (v[0], q(0.5), q(0.9), v[-1])
print("CPU s per recording as recorded (%.1f-%.1f min), %d recordings: %s; %d within 30 s"
      % (min(minutes), max(minutes), len(raw), spread(raw), sum(x <= 30.0 for x in raw)))
print("CPU s scaled to 10 minutes in proportion (an upper bound): %s" % spread(per10))
print("planter-fit CPU per 10-minute recording, one core, scaled in proportion: %d of %d within 30 s"
      % (sum(x <= 30.0 for x in per10), len(per10)))'

