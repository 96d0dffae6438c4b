#pragma once
// The disturbance suite's cases (issue 49, "What to build" 1): a name, the loop the case is
// aimed at, and its settings by disturbance key. Values marked assumed in the .cpp have no
// source: each is a plausible top of what a field gives, said so beside it.
#include <string>
#include <utility>
#include <vector>

#include "sim/runner/scenario.h"

namespace planter::sim {

struct RobustnessCase {
  std::string name;
  std::string aimed_at;  // sigma, clamp, depth, machine (faults) or all (combinations)
  std::string what;
  std::vector<std::pair<std::string, double>> settings;
};

// The cases on `base` for routes of `distance_m` (mid-run changes at its middle), then
// `combinations` random ones (Latin hypercube, seeded by the scenario's seed).
std::vector<RobustnessCase> robustness_cases(const Scenario& base, double distance_m,
                                             int combinations);

}  // namespace planter::sim
