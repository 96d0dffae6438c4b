#pragma once
// planter-sim sweep: the paper's experiment end to end. The Box-Behnken design on contact area,
// disc speed and depth, each point run with replicates until its damage rate is resolved, the
// quadratic response surfaces with their analysis of variance, and the desirability optimum.
#include <string>

namespace planter::sim {

struct SweepOptions {
  double distance_m = 30.0;           // per run
  int replicates = 2;                 // per design point, at least
  int max_replicates = 12;            // per design point, while damage is not yet resolved
  double damage_precision_pts = 0.5;  // the standard error of a point's damage rate, goal
  int jobs = 0;                       // runs at a time (0: one per core)
  bool force = false;
};

// Writes OUT/{sweep.csv,sweep.json,report.html}; prints the figures, the optimum last.
int run_sweep(const std::string& scenario_path, const std::string& out_dir, const SweepOptions& o);

}  // namespace planter::sim
