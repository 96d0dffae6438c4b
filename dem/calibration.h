#pragma once
// The paper's calibration workflow on the compression test: Plackett-Burman screening of
// 8 factors, steepest ascent on the significant ones towards the target peak force,
// Box-Behnken around the best step with a quadratic response surface and its ANOVA, the
// optimum, and a verification run there. Each stage's runs are a plan on an executor
// (plan/executor.h: `jobs` threads here, or a Slurm job array); each finished run is kept in
// DIR/runs/ under a hash of its parameters (calibration_runs.h), so an interrupted calibration
// resumes where it stopped and never runs the same simulation twice.
#include <functional>
#include <string>
#include <vector>

#include "dem/compression_report.h"
#include "doe/doe.h"
#include "plan/executor.h"

namespace planter::dem {

// The designs and their analysis are shared with planter-sim's sweep (doe/).
using doe::Anova;
using doe::TermTest;

// One factor of the screening: its name, how it sets a setup, and its low/high levels.
// Stiffness and strength span decades, so they are coded on a log scale.
struct Factor {
  std::string name;
  std::string unit;
  double low = 0.0;
  double high = 0.0;
  bool log_scale = false;
  std::function<void(CompressionSetup&, double)> apply;
  [[nodiscard]] double value(double coded) const;
};

// X1..X8: bond stiffness, bond strength, Poisson's ratio, seedling restitution, seedling
// rolling friction, seedling static friction, seedling-steel restitution, seedling-steel
// static friction.
std::vector<Factor> screening_factors();

struct CalibrationOptions {
  double target_N = 140.6;
  double target_displacement_mm = 0.0;  // > 0: the refinement also places the peak there
  int refinement_runs = 10;             // beyond the paper's workflow; 0 = none
  int jobs = 1;
  plan::ExecutorOptions executor;  // where each stage's runs execute (its jobs: `jobs`)
  int max_new_runs = -1;  // stop (as if interrupted) after this many new runs; -1 = no limit
  CompressionSetup base;
  std::string out_dir;
  double significance = 0.05;
};

struct DesignRun {
  std::vector<double> coded;
  CompressionSetup setup;
  CompressionResult result;
  bool reused = false;
};

struct CalibrationReport {
  std::vector<Factor> factors;
  std::vector<DesignRun> screening;
  Anova screening_anova;
  std::vector<int> chosen;  // factor indices for steepest ascent and Box-Behnken
  std::string chosen_reason;
  std::vector<DesignRun> ascent;
  int best_step = 0;
  std::vector<DesignRun> box_behnken;
  std::vector<double> bb_low, bb_centre, bb_high;  // the 3 chosen factors' real values
  Anova surface;
  Eigen::Vector3d optimum_coded = Eigen::Vector3d::Zero();
  double predicted_N = 0.0;
  DesignRun verification;
  // Refinement: the peak force scales with the bond stiffness S at a fixed sigma_c / S, and
  // the collapse point moves with sigma_c / S; secant steps on both from the verification.
  std::vector<DesignRun> refinement;
  DesignRun calibrated;            // the best of the verification and the refinement
  std::string refinement_stopped;  // why the refinement stopped early ("": it did not)
  int new_runs = 0;
  int reused_runs = 0;
  bool complete = false;  // false when max_new_runs stopped it
};

// Runs the workflow. Throws std::runtime_error for an unwritable output directory.
CalibrationReport calibrate(const CalibrationOptions& options,
                            const std::function<void(const std::string&)>& progress);
void write_calibration_outputs(const CalibrationOptions& options, const CalibrationReport& r);

}  // namespace planter::dem
