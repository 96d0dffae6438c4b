#pragma once
// --executor and its options, the same on every multi-run command (planter-sim's sweep,
// sensitivity and montecarlo, planter-dem's calibrate): where the runs execute (plan/executor.h).
#include <CLI/CLI.hpp>

#include "config/cli_range.h"
#include "plan/executor.h"

namespace planter::apps {

inline void add_executor_options(CLI::App& cmd, plan::ExecutorOptions& ex) {
  cmd.add_option("--executor", ex.kind, "where the runs execute: local or slurm")
      ->capture_default_str()
      ->check(CLI::IsMember({"local", "slurm"}));
  cmd.add_flag("--plan-only", ex.plan_only,
               "write the plan (and with slurm its sbatch script) and run nothing");
  cmd.add_option("--partition", ex.partition, "slurm: the partition");
  cmd.add_option("--account", ex.account, "slurm: the account");
  cmd.add_option("--time-limit", ex.time_limit,
                 "slurm: each task's limit (sbatch --time; default ten times a run timed here)");
  cmd.add_option("--throttle", ex.throttle, "slurm: most tasks at once (0: no limit)")
      ->check(config::finite_range(0, 100000));
  cmd.add_option("--sbatch-args", ex.sbatch_args, "slurm: more arguments for sbatch");
  cmd.add_option("--runs-per-task", ex.runs_per_task,
                 "slurm: runs each array task executes in turn (short runs: several)")
      ->capture_default_str()
      ->check(config::finite_range(1, 100000));
  cmd.add_option("--poll", ex.poll_s, "slurm: seconds between looks at the queue")
      ->capture_default_str()
      ->check(config::finite_range(0.1, 600.0));
}

}  // namespace planter::apps
