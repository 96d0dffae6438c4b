#pragma once
// planter-sim sensitivity: which of the model's values the simulator's conclusions rest on.
// Morris's elementary effects (Morris, "Factorial sampling plans for preliminary computational
// experiments", Technometrics 33(2), 1991; mu* after Campolongo, Cariboni and Saltelli, 2007)
// over every value of sim/plant/model_values.cpp, each across its plausible range, for the
// uprightness, the damage rate and the share of seedlings turned in the clamp at the scenario's
// operating point. Seeded: trajectory t runs every point with the seed + t (common random
// numbers within a trajectory, replicated across them).
#include <string>

#include "sim/runner/executor.h"

namespace planter::sim {

struct SensitivityOptions {
  int trajectories = 6;      // r; runs = r (k + 1)
  double distance_m = 10.0;  // per run
  int jobs = 0;              // runs at a time (0: one per core)
  bool optimum = false;      // also the paper's design at each point: where the optimum goes
  bool force = false;
  ExecutorOptions executor;  // where the runs execute (executor.h); plans in OUT.runs/
};

// Writes OUT/{sensitivity.csv,sensitivity.json,report.html}; prints the ranking, the spread of
// the figures last.
int run_sensitivity(const std::string& scenario_path, const std::string& out_dir,
                    const SensitivityOptions& o);

}  // namespace planter::sim
