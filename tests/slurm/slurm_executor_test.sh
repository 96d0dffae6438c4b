#!/usr/bin/env bash
# The sweep through a real one-node Slurm cluster (scripts/slurm-cluster.sh; issue 31):
# 1. --executor slurm gives the same sweep.json as --executor local;
# 2. a task cancelled with scancel leaves no result, and running the command again submits
#    only the missing runs (the complete ones untouched) and completes the same sweep;
# 3. a task cancelled, or crashed (SIGSEGV), while it runs, the executor following the job, is
#    reported by its index and its state (squeue's, or sacct's where the cluster keeps
#    accounting); nothing gathered;
# 4. an unknown partition and a Slurm that cannot be reached are each one message that says what
#    to fix (the partitions there; sinfo and SLURM_CONF), exit 1, and nothing gathered;
# 5. planter-dem's calibration through the cluster, each stage's runs one job array, gives the
#    same calibration.json as the local one.
# Usage: slurm_executor_test.sh PLANTER_SIM SOURCE_DIR PLANTER_DEM
set -euo pipefail
sim=$1 src=$2 dem=$3
work=$(mktemp -d)
cleanup() {
  "$src/scripts/slurm-cluster.sh" stop "$work/cluster" >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }
eval "$("$src/scripts/slurm-cluster.sh" start "$work/cluster")"
same_sweep() {  # same_sweep A B: the two sweep.json hold the same results
  python3 - "$1/sweep.json" "$2/sweep.json" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
sys.exit(0 if a == b else 1)
PY
}
args=(sweep "$src/scenarios/zhangqiu-field.toml" --distance 3 --replicates 1 --max-replicates 1)

"$sim" "${args[@]}" --out "$work/local" --jobs 2 >"$work/local.out"
"$sim" "${args[@]}" --out "$work/slurm" --executor slurm --poll 0.3 >"$work/slurm.out" \
  2>"$work/slurm.err" || { cat "$work/slurm.err"; fail "the sweep through Slurm failed"; }
grep -q "submitted 14 runs as Slurm job" "$work/slurm.err" ||
  fail "the design's 15 runs were not submitted as one array after the timed run: $(cat "$work/slurm.err")"
same_sweep "$work/local" "$work/slurm" || fail "sweep.json through Slurm differs from the local one"
echo "slurm: the 3 m sweep through the cluster equals the local one (sweep.json)"

# --sbatch-args reaches sbatch as words, never through a shell (issue 53): a $(...) in it is
# text for sbatch, not a command for this machine.
"$sim" montecarlo "$src/scenarios/zhangqiu-field.toml" --runs 3 --distance 1 --out "$work/args" \
  --executor slurm --poll 0.3 --sbatch-args "--comment=\$(touch\${IFS}$work/pwned)" \
  >/dev/null 2>"$work/args.err" || { cat "$work/args.err"; fail "montecarlo with --sbatch-args failed"; }
[ ! -e "$work/pwned" ] || fail "--sbatch-args went through a shell: the \$(touch ...) in it ran"
echo "slurm: --sbatch-args reaches sbatch as words (the \$(touch ...) in it ran nothing)"

# A killed task: the plan submitted by hand (one task at a time), its last task cancelled.
"$sim" "${args[@]}" --out "$work/killed" --executor slurm --plan-only --throttle 1 \
  >"$work/plan-only.out" || fail "--plan-only failed"
plan=$work/killed.runs/stage-1
[ -s "$plan/plan.json" ] && [ -s "$plan/plan.sbatch" ] || fail "--plan-only wrote no plan or script"
[ ! -e "$plan/runs" ] || [ -z "$(ls "$plan/runs")" ] || fail "--plan-only ran something"
job=$(sbatch --parsable "$plan/plan.sbatch")
scancel "${job}_14"
for _ in $(seq 600); do
  [ -z "$(squeue -h -j "$job" -t PENDING,RUNNING,CONFIGURING,COMPLETING -o %i)" ] && break
  sleep 0.2
done
missing=0
declare -A before
for i in $(seq 0 14); do
  d=$(printf '%s/runs/%05d' "$plan" "$i")
  if [ -s "$d/run.json" ]; then before[$i]=$(stat -c %Y.%y "$d/run.json"); else missing=$((missing + 1)); fi
done
[ "$missing" -ge 1 ] || fail "the cancelled task left a result"
"$sim" "${args[@]}" --out "$work/killed" --executor slurm --time-limit 5 --poll 0.3 \
  >"$work/resumed.out" 2>"$work/resumed.err" || { cat "$work/resumed.err"; fail "the re-run failed"; }
grep -q "sweep: submitted $missing runs as Slurm job" "$work/resumed.err" ||
  fail "the re-run did not submit exactly the $missing missing runs: $(grep submitted "$work/resumed.err")"
for i in "${!before[@]}"; do
  d=$(printf '%s/runs/%05d' "$plan" "$i")
  [ "$(stat -c %Y.%y "$d/run.json")" = "${before[$i]}" ] || fail "complete run $i was run again"
done
same_sweep "$work/local" "$work/killed" || fail "the resumed sweep differs from the local one"
echo "slurm: a cancelled task, then the command again: $missing missing run(s) submitted," \
  "$((15 - missing)) kept, and the same sweep.json"

# A task ended while it runs, the executor following its job (one task at a time; 300 m runs,
# about 4 s each, so the signal lands before the run ends): cancelled with scancel, and crashed
# (SIGSEGV to the task's processes).
signalled() {  # signalled NAME STATE [SCANCEL ARGS...]
  local name=$1 state=$2 follower task="" job status=0
  shift 2
  "$sim" sweep "$src/scenarios/zhangqiu-field.toml" --distance 300 --replicates 1 \
    --max-replicates 1 --out "$work/$name" --executor slurm --throttle 1 --time-limit 5 \
    --poll 0.3 >"$work/$name.out" 2>"$work/$name.err" &
  follower=$!
  for _ in $(seq 600); do
    job=$(sed -n 's/.*submitted [0-9]* runs as Slurm job \([0-9]*\).*/\1/p' "$work/$name.err")
    [ -n "$job" ] && task=$(squeue -h -r -j "$job" -t RUNNING -o %i | head -1)
    [ -n "$task" ] && break
    sleep 0.1
  done
  [ -n "$task" ] || { kill "$follower"; fail "$name: no task of the followed sweep was seen running"; }
  # scancel exits non-zero after signalling a batch task with --full (seen: 229); what counts
  # is the task's end, checked below.
  scancel "$@" "$task" || true
  # The array's tasks still pending would run one at a time, 14 runs of 300 m (about 25 s) that
  # say nothing more here: they are cancelled too, and are reported with the signalled one.
  scancel -t PENDING "$job" || true
  wait "$follower" || status=$?
  [ "$status" -ne 0 ] || fail "$name: a sweep with a $name task exited 0"
  grep -q "task $task ended $state without its result" "$work/$name.err" ||
    fail "$name: task $task was not reported $state: $(tail -5 "$work/$name.err")"
  [ ! -e "$work/$name/sweep.json" ] || fail "$name: a sweep was gathered from incomplete runs"
  echo "slurm: task $task $name while it ran is reported as $state; nothing gathered"
}
signalled cancelled CANCELLED
signalled crashed FAILED --signal=11 --full

# Bad input: a partition the cluster has not, and a Slurm that cannot be reached.
refused() {  # refused NAME PATTERN SLURM_CONF [ARGS...]: exit 1, the pattern said, nothing gathered
  local name=$1 pattern=$2 conf=$3 rc=0
  shift 3
  SLURM_CONF=$conf "$sim" "${args[@]}" --out "$work/$name" --executor slurm --time-limit 5 "$@" \
    >"$work/$name.out" 2>&1 || rc=$?
  [ "$rc" -eq 1 ] || fail "$name: exit $rc, wanted 1: $(cat "$work/$name.out")"
  grep -q -- "$pattern" "$work/$name.out" || fail "$name: /$pattern/ not said: $(cat "$work/$name.out")"
  [ ! -e "$work/$name/sweep.json" ] || fail "$name: a sweep was gathered"
}
refused partition "the partitions here: planter" "$SLURM_CONF" --partition nosuch
grep -q "invalid partition specified: nosuch" "$work/partition.out" ||
  fail "sbatch's own words on the partition were not passed on: $(cat "$work/partition.out")"
# The cluster's own configuration with its controller's port where nothing listens: sbatch gives
# up in about 9 s (a missing configuration file takes 60 s: it looks for the controller in DNS).
sed 's/^SlurmctldPort=.*/SlurmctldPort=16899/' "$SLURM_CONF" >"$work/down.conf"
refused unreachable "Slurm is not reachable from here: check .sinfo. (and SLURM_CONF)" \
  "$work/down.conf"
grep -q "Unable to contact slurm controller" "$work/unreachable.out" ||
  fail "sbatch's own words on the controller were not passed on: $(cat "$work/unreachable.out")"
echo "slurm: an unknown partition and an unreachable Slurm each say what to fix; nothing gathered"

# planter-dem's calibration: a coarse seedling (2.5 mm particles, the platen 100 times the
# paper's speed: a run in a fifth of a second) so every stage goes through the cluster in
# seconds; what is compared is where the runs ran, not the seedling.
printf '[seedling]\nparticle_radius_mm = 2.5\n[test]\nspeedup = 100\n' >"$work/coarse.toml"
"$dem" calibrate --params "$work/coarse.toml" --out "$work/dem-local" --jobs 2 \
  >"$work/dem-local.out" 2>/dev/null || fail "the local calibration failed"
"$dem" calibrate --params "$work/coarse.toml" --out "$work/dem-slurm" --executor slurm --runs-per-task 4 \
  --time-limit 5 --poll 0.3 >"$work/dem-slurm.out" 2>"$work/dem-slurm.err" ||
  { cat "$work/dem-slurm.err"; fail "the calibration through Slurm failed"; }
arrays=$(grep -c "submitted [0-9]* runs as Slurm job" "$work/dem-slurm.err" || true)
[ "$arrays" -ge 4 ] || fail "the calibration's stages were not submitted as job arrays ($arrays)"
python3 - "$work/dem-local/calibration.json" "$work/dem-slurm/calibration.json" <<'PY' ||
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
sys.exit(0 if a == b else 1)
PY
  fail "calibration.json through Slurm differs from the local one"
echo "slurm: planter-dem's calibration, $arrays job arrays, equals the local one (calibration.json)"
