#pragma once
// planter-sim's run plans (run_plan.h) on an executor (plan/executor.h): each run is
// `planter-sim plan-run PLAN INDEX` into DIR/runs/NNNNN; run here, the plan's scenario is
// loaded once. The runs' summaries come back in the plan's order, and only when every run is
// complete.
#include <string>
#include <vector>

#include "plan/executor.h"
#include "sim/runner/run_plan.h"
#include "sim/runner/summary.h"

namespace planter::sim {

using plan::executor_refusal;
using plan::ExecutorOptions;
using plan::PlanWritten;

// Places the plan in `plan_dir` (place_plan), runs what is missing and returns every run's
// summary in plan order. `label` names the work in progress lines on a terminal. Throws
// std::runtime_error listing failed runs (index, exit, log), or PlanWritten.
std::vector<Summary> execute_plan(const std::string& plan_dir, const RunPlan& plan,
                                  const ExecutorOptions& o, const std::string& label);

}  // namespace planter::sim
