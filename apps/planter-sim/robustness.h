#pragma once
// planter-sim robustness: the controller under disturbance (issue 49). Every case is the base
// scenario with a few disturbances set (sim/runner/disturbance_keys.h): each hidden effect
// alone, stems, lips, the load cell, slip, speed, stops, soil, terrain, targets, a silent
// node, the e-stop, and random combinations drawn as montecarlo draws them. Each case runs
// twice, with the sigma loop and with the paper's drive (the disc at a fixed ratio from the
// soil wheel), as one plan on the local or Slurm executor. Each loop is scored against its
// goal (firmware/control/loop_goals.h): held, alarmed (its alarm within a second) or silent.
#include <string>

#include "sim/runner/executor.h"

namespace planter::sim {

struct RobustnessOptions {
  double distance_m = 12.0;  // per case
  int combinations = 64;     // random combinations of disturbances
  int jobs = 0;
  bool force = false;
  ExecutorOptions executor;
};

// Writes OUT/{robustness.json,robustness.csv,report.html}; prints the table and, last,
// "robustness: N of M cases held, S silent". Returns 0 (the verdicts are the output).
int run_robustness(const std::string& scenario_path, const std::string& out_dir,
                   const RobustnessOptions& o);

}  // namespace planter::sim
