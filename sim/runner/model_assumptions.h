#pragma once
// The model assumptions of a run, written from the configuration that ran (not from a text that
// can fall behind it): the report and summary.json print them.
#include <string>
#include <vector>

#include "sim/runner/scenario.h"

namespace planter::sim {

// One plain sentence per assumption, with the values used.
std::vector<std::string> model_assumptions(const Scenario& sc);

}  // namespace planter::sim
