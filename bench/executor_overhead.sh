#!/usr/bin/env bash
# What the executors cost per run, beside what a run costs (issue 31): a sweep of 21 short runs
# (the 15 design points and the 6 clamp forces, 0.5 m each), timed whole, through
# --executor local (one run at a time, in this process) and through --executor slurm on a
# one-node cluster started here (scripts/slurm-cluster.sh; one run a task, then eight). The
# runs' own simulation time (their summary.json's wall_seconds) taken off leaves the
# executor's part: planning, writing each run's output set, submitting and scheduling each
# task, following the queue, and gathering. Printed last as a ratio to one 30 m field run
# (scripts/field-trial.sh's scenario), timed here too.
# Usage: bench/executor_overhead.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
sim=$build/apps/planter-sim/planter-sim
work=$(mktemp -d)
cleanup() {
  "$root/scripts/slurm-cluster.sh" stop "$work/cluster" >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT
now() { date +%s.%N; }
calc() { awk "BEGIN { print $1 }"; }  # awk: in every Debian, unlike bc
field_start=$(now)
"$sim" run "$root/scenarios/zhangqiu-field.toml" --out "$work/field" --quiet >/dev/null
field_s=$(calc "$(now) - $field_start")
runs_sim_s() {  # the runs' own simulation wall time, summed over OUT.runs
  python3 - "$1" <<'PY'
import glob, json, sys
print(sum(json.load(open(f))["wall_seconds"] for f in glob.glob(sys.argv[1] + "/*/runs/*/summary.json")))
PY
}
args=(sweep "$root/scenarios/zhangqiu-field.toml" --distance 0.5 --replicates 1 --max-replicates 1)
start=$(now)
"$sim" "${args[@]}" --out "$work/local" --jobs 1 >/dev/null
local_s=$(calc "$(now) - $start")
local_sim=$(runs_sim_s "$work/local.runs")
eval "$("$root/scripts/slurm-cluster.sh" start "$work/cluster" 2>/dev/null)"
start=$(now)
"$sim" "${args[@]}" --out "$work/slurm" --executor slurm --time-limit 5 --poll 0.2 >/dev/null 2>&1
slurm_s=$(calc "$(now) - $start")
slurm_sim=$(runs_sim_s "$work/slurm.runs")
start=$(now)
"$sim" "${args[@]}" --out "$work/batched" --executor slurm --time-limit 5 --poll 0.2 \
  --runs-per-task 8 >/dev/null 2>&1
batched_s=$(calc "$(now) - $start")
batched_sim=$(runs_sim_s "$work/batched.runs")
n=21
local_over=$(calc "($local_s - $local_sim) / $n")
slurm_over=$(calc "($slurm_s - $slurm_sim) / $n")
batched_over=$(calc "($batched_s - $batched_sim) / $n")
printf 'one 30 m field run: %.3f s wall\n' "$field_s"
printf 'local executor: %d runs in %.2f s, of which the runs simulated %.2f s: %.3f s a run\n' \
  "$n" "$local_s" "$local_sim" "$local_over"
printf 'slurm executor (one node, 2 CPUs): %d runs in %.2f s, of which the runs simulated %.2f s: %.3f s a run\n' \
  "$n" "$slurm_s" "$slurm_sim" "$slurm_over"
printf 'slurm executor, 8 runs a task: %d runs in %.2f s, of which the runs simulated %.2f s: %.3f s a run\n' \
  "$n" "$batched_s" "$batched_sim" "$batched_over"
printf 'executor overhead per run against one 30 m field run: local %.2f, slurm %.2f (8 runs a task: %.2f)\n' \
  "$(calc "$local_over / $field_s")" "$(calc "$slurm_over / $field_s")" \
  "$(calc "$batched_over / $field_s")"
