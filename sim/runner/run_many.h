#pragma once
// Many independent lockstep runs, `jobs` at a time, each its own runner: the sweep's force
// curve and the sensitivity analysis. A run's result does not depend on the order or thread it
// ran in (each scenario carries its seed).
#include <string>
#include <vector>

#include "sim/runner/scenario.h"
#include "sim/runner/summary.h"

namespace planter::sim {

// `label` names the work on a terminal ("sweep: 12 of 65 runs"), updated as runs finish; on
// anything else (a log, a pipe) nothing is printed. Empty: never.
std::vector<Summary> run_many(const std::vector<Scenario>& scenarios, int jobs,
                              const std::string& label = "");

}  // namespace planter::sim
