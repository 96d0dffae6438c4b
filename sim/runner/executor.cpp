#include "sim/runner/executor.h"

#include <mutex>
#include <optional>

#include "plan/folder_lock.h"

namespace planter::sim {

std::vector<Summary> execute_plan(const std::string& plan_dir, const RunPlan& plan,
                                  const ExecutorOptions& o, const std::string& label) {
  const plan::FolderLock lock(
      plan_dir,
      "another planter-sim is running this plan now (wait for it, or give --out another)");
  place_plan(plan_dir, plan, o.replace_other_plan);
  const std::string plan_path = plan_dir + "/plan.json";
  // The scenario is loaded (and checked against the plan's key) once, by the first run here.
  std::once_flag loaded;
  std::optional<Scenario> base;
  plan::PlanRuns runs;
  runs.dir = plan_dir;
  runs.count = plan.runs.size();
  runs.complete = [&](std::size_t i) { return run_complete(plan_dir, i); };
  runs.run_here = [&](std::size_t i) {
    std::call_once(loaded, [&] { base = plan_base(plan_path, plan, o.made_by); });
    run_planned(plan_dir, *base, plan.runs[i], i);
  };
  runs.what = "planter-sim";
  if (o.kind == "slurm")  // the program's own path, only where a task needs it
    runs.task_command =
        plan::shell_quoted(plan::task_program(o)) + " plan-run " + plan::shell_quoted(plan_path);
  runs.by_hand = "planter-sim plan-run " + plan_path + " INDEX, for each INDEX of the plan's runs";
  plan::execute(runs, o, label);
  std::vector<Summary> out;
  out.reserve(plan.runs.size());
  for (std::size_t i = 0; i < plan.runs.size(); ++i) out.push_back(read_run_summary(plan_dir, i));
  return out;
}

}  // namespace planter::sim
