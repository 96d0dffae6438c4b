#pragma once
// planter-sim montecarlo: what the figures may be, given what is not known. Every model value
// (sim/plant/model_values.cpp) is drawn across its plausible range by Latin hypercube sampling
// (McKay, Beckman and Conover, Technometrics 21(2), 1979), each run with its own seed (its own
// seedlings, terrain and sensor noise: another season on the same field). The runs are a plan
// (run_plan.h) executed locally or as a Slurm job array (executor.h), so a study of thousands of
// runs resumes and scales like a sweep.
#include <string>

#include "sim/runner/executor.h"

namespace planter::sim {

struct MonteCarloOptions {
  int runs = 32;
  double distance_m = 10.0;  // per run
  int jobs = 0;              // runs at a time (0: one per core)
  bool force = false;
  ExecutorOptions executor;
  // Each draw also against each constant force of the sweep's trade-off (grip_benchmark.h).
  bool grip = false;
  // Stems of this diameter range in every run, "MIN-MAX" in mm (empty: the scenario's).
  std::string stems_mm;
};

// Writes OUT/{montecarlo.csv,montecarlo.json}; prints each figure's mean with its standard
// error and its 5-95 % range, the paper's figures beside them, last.
int run_monte_carlo(const std::string& scenario_path, const std::string& out_dir,
                    const MonteCarloOptions& o);

}  // namespace planter::sim
