#pragma once
// planter-sim sweep: the paper's experiment end to end. The Box-Behnken design on contact area,
// disc speed and depth, each point run with replicates until its damage rate is resolved, the
// quadratic response surfaces with their analysis of variance, and the desirability optimum.
#include <string>
#include <vector>

#include "sim/runner/executor.h"
#include "sim/runner/scenario.h"
#include "sim/runner/summary.h"

namespace planter::sim {

struct SweepOptions {
  double distance_m = 30.0;           // per run
  int replicates = 2;                 // per design point, at least
  int max_replicates = 12;            // per design point, while damage is not yet resolved
  double damage_precision_pts = 0.5;  // the standard error of a point's damage rate, goal
  int jobs = 0;                       // runs at a time (0: one per core)
  bool force = false;
  // Where the runs execute (executor.h): local processes or a Slurm job array. The plans and
  // each run's result are kept in OUT.runs/ beside OUT, so a second call runs only what is
  // missing.
  ExecutorOptions executor;
};

// The folder of a multi-run command's plans and runs: OUT.runs beside OUT.
std::string runs_folder(const std::string& out_dir);
// The plan of one run of the paper's design (point p of the Box-Behnken design; what the
// sensitivity analysis runs to see where the optimum goes) on `at`: its seed the run's seed + p,
// after the run's own model values.
std::vector<PlannedRun> design_runs(const Scenario& base, const PlannedRun& at);
// The sweep's and the sensitivity analysis's executor for `--jobs` and `--force`.
ExecutorOptions executor_for(const ExecutorOptions& o, int jobs, bool force);

// The clamp force set-points of the grip's trade-off (the sweep's centre, the grip benchmark).
inline constexpr double kClampForceCurve_N[] = {40.0, 60.0, 80.0, 90.0, 100.0, 120.0};

// Writes OUT/{sweep.csv,sweep.json,report.html}; prints the figures, the optimum last.
int run_sweep(const std::string& scenario_path, const std::string& out_dir, const SweepOptions& o);

struct DesignOptimum {
  double contact_area_mm2 = 0, disc_speed_radps = 0, depth_mm = 0, desirability = 0;
  // The terms of uprightness's quadratic significant at p < 0.05 ("A", "BC", "C^2", ...), with
  // the paper's list for comparison.
  std::vector<std::string> significant_terms;
};
// The terms of uprightness the paper found significant (its Tables 5-6).
const std::vector<std::string>& paper_significant_terms();

// The paper's optimum and centre point (its optimisation): printed beside the model's as a
// comparison, never a target.
inline constexpr double kPaperOptimum[3] = {255.0, 0.278, 102.0};  // mm^2, rad/s, mm
inline constexpr double kPaperCentreUprightness_pct = 94.8, kPaperCentreDamage_pct = 3.0;
// An optimum as the tools print it: "255 mm^2, 0.278 rad/s, 102 mm".
std::string optimum_text(double area_mm2, double disc_speed_radps, double depth_mm);
// The span of the design's factor (0 contact area, 1 disc speed, 2 depth), in its unit.
double design_span(int factor);
// The desirability optimum of design_runs' results, in the same order.
DesignOptimum design_optimum(const std::vector<Summary>& results);

}  // namespace planter::sim
