#pragma once
// Executors of a plan of self-contained runs (issue 31), whatever the runs compute: every run
// not yet complete runs here (`local`: `jobs` threads in this process) or as a task of a Slurm
// job array (`slurm`: the plan's task command per run, sbatch --array with a throttle, followed
// with squeue, each task's log beside the plan). Either writes each run's output the same way
// (the program's own whole-or-nothing files), so the two give the same results and resume each
// other's plans. A run that failed is reported by its index and its log, and the caller gathers
// nothing until every run is complete. A second call with the same plan runs only what is
// missing. planter-sim's plans (sim/runner/run_plan.h) and planter-dem's calibration stages
// (dem/calibration.h) both run here.
#include <cstddef>
#include <functional>
#include <string>

namespace planter::plan {

struct ExecutorOptions {
  std::string kind = "local";  // "local" or "slurm"
  int jobs = 0;                // local: runs at a time (0: one per core)
  std::string program;         // slurm: the program each task executes ("": this one)
  std::string made_by;         // the program's version, which a plan's key holds
  // Slurm: sbatch's --partition, --account, --time (per task; "": ten times the first run's
  // wall time measured here, at least a minute), the array's throttle (0: none), and more
  // arguments for sbatch as they would be typed.
  std::string partition, account, time_limit, sbatch_args;
  int throttle = 0;
  // Runs one task executes, one after another: short runs (a 30 m field run takes well under a
  // second) cost less than the scheduler spends on a task (about 1.6 s on the test cluster).
  int runs_per_task = 1;
  double poll_s = 2.0;
  // Write the plan and (slurm) its sbatch script, and run nothing.
  bool plan_only = false;
  // A folder holding another plan (other inputs, another build) is replaced, not refused.
  bool replace_other_plan = false;
};

// Why the options cannot be used ("" when they can): an unknown executor, sbatch missing, a
// control character in a value that goes into the Slurm script (a newline there would end its
// line and drop the directives after it). sbatch runs without a shell: --sbatch-args is split
// at blanks and each word is one argument.
std::string executor_refusal(const ExecutorOptions& o);
// `what`: a control character in `value`, named with its byte ("" when there is none).
std::string control_character_refusal(const std::string& what, const std::string& value);

// The program a Slurm task runs: `o.program`, or this process's own executable.
std::string task_program(const ExecutorOptions& o);

// A word for a shell, quoted.
std::string shell_quoted(const std::string& s);

// Thrown with --plan-only: the plan is written, nothing ran.
struct PlanWritten {
  std::string dir;
  std::string how_to_run;  // the command that runs it
};

// A plan's runs as an executor sees them.
struct PlanRuns {
  std::string dir;  // the plan's folder: logs/, tasks.txt and plan.sbatch go here
  std::size_t count = 0;
  std::function<bool(std::size_t)> complete;  // run i's output is there, whole
  std::function<void(std::size_t)> run_here;  // runs run i in this process; throws on failure
  // Shell words that run one run when its index follows them (a Slurm task's command), and
  // the same for a person running the plan by hand.
  std::string task_command;
  std::string by_hand;
  std::string what = "plan";  // names the work in messages ("sweep", "dem screening")
};

// The Slurm job array's script for `tasks` tasks: task T runs the runs on line T + 1 of
// DIR/tasks.txt, one after another. The values it writes must have passed executor_refusal()
// and the folder control_character_refusal() (its fuzz target holds it to that).
std::string sbatch_script(const PlanRuns& runs, std::size_t tasks, const ExecutorOptions& o,
                          const std::string& label, const std::string& time_limit);

// Runs every run of `runs` not yet complete with the executor `o` and returns when all are
// complete. `label` names the work in progress lines on a terminal. Throws std::runtime_error
// listing failed runs (index, reason, log), or PlanWritten.
void execute(const PlanRuns& runs, const ExecutorOptions& o, const std::string& label);

}  // namespace planter::plan
