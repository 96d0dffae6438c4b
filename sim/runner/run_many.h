#pragma once
// Many independent lockstep runs, `jobs` at a time, each its own runner: the sweep's force
// curve and the sensitivity analysis. A run's result does not depend on the order or thread it
// ran in (each scenario carries its seed).
#include <vector>

#include "sim/runner/scenario.h"
#include "sim/runner/summary.h"

namespace planter::sim {

std::vector<Summary> run_many(const std::vector<Scenario>& scenarios, int jobs);

}  // namespace planter::sim
