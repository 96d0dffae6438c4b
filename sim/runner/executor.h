#pragma once
// Executors of a run plan (run_plan.h, issue 31): every run not yet complete runs here
// (`local`: `jobs` threads in this process, the plan's scenario loaded once) or as a task of a
// Slurm job array (`slurm`: `planter-sim plan-run PLAN INDEX` per run, sbatch --array with a
// throttle, followed with squeue, each task's log beside the plan). Either writes each run's
// output set the same way, so the two give the same results and resume each other's plans. The
// runs' summaries come back in the plan's order; a run that failed is reported by its index and its
// log, and nothing is gathered until every run is complete. A second call with the same plan runs
// only what is missing.
#include <string>
#include <vector>

#include "sim/runner/run_plan.h"
#include "sim/runner/summary.h"

namespace planter::sim {

struct ExecutorOptions {
  std::string kind = "local";  // "local" or "slurm"
  int jobs = 0;                // local: runs at a time (0: one per core)
  std::string program;         // slurm: the planter-sim each task executes ("": this one)
  std::string made_by;         // the program's version, which the plan's key holds
  // Slurm: sbatch's --partition, --account, --time (per task; "": ten times the first run's
  // wall time measured here, at least a minute), the array's throttle (0: none), and more
  // arguments for sbatch as they would be typed.
  std::string partition, account, time_limit, sbatch_args;
  int throttle = 0;
  // Runs one task executes, one after another: short runs (a 30 m field run takes well under a
  // second) cost less than the scheduler spends on a task (about 1.6 s on the test cluster).
  int runs_per_task = 1;
  double poll_s = 2.0;
  // Write DIR/plan.json and (slurm) DIR/plan.sbatch, and run nothing.
  bool plan_only = false;
  // A folder holding another plan (other inputs, another build) is replaced, not refused.
  bool replace_other_plan = false;
};

// Why the options cannot be used ("" when they can): an unknown executor, sbatch missing.
std::string executor_refusal(const ExecutorOptions& o);

// Thrown by execute_plan with --plan-only: the plan is written, nothing ran.
struct PlanWritten {
  std::string dir;
  std::string how_to_run;  // the command that runs it
};

// Places the plan in `plan_dir` (place_plan), runs what is missing and returns every run's
// summary in plan order. `label` names the work in progress lines on a terminal. Throws
// std::runtime_error listing failed runs (index, exit, log), or PlanWritten.
std::vector<Summary> execute_plan(const std::string& plan_dir, const RunPlan& plan,
                                  const ExecutorOptions& o, const std::string& label);

}  // namespace planter::sim
