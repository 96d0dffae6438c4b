#pragma once
// A plan of self-contained runs (issue 31): each run is the base scenario with its own seed,
// distance and settings, executed as `planter-sim plan-run PLAN INDEX` into its own output set
// (DIR/runs/NNNNN, whole or nothing), so a run's result does not depend on where, when or in
// what order it ran. The multi-run commands write a plan, hand it to an executor (local
// processes or a Slurm job array: executor.h) and gather the runs' summaries.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sim/runner/scenario.h"
#include "sim/runner/summary.h"

namespace planter::sim {

struct OperatingPoint {
  double sigma = 1.5, depth_mm = 100.0, contact_area_mm2 = 255.0;
};

struct PlannedRun {
  std::uint64_t seed = 1;
  double distance_m = 10.0;  // without stops
  std::optional<OperatingPoint> operating_point;
  std::optional<double> clamp_setpoint_N;  // the ceiling raised to 20 N above it if needed
  std::optional<bool> per_stem_grip;       // the clamp's grip: each stem's own, or one set-point
  bool clamp_told_each_stem = false;       // Scenario::clamp_told_each_stem: a bound, no machine
  // Model values set by their keys (sim/plant/model_values.h), before the operating point.
  std::vector<std::pair<std::string, double>> values;
  // Disturbances set by their keys (disturbance_keys.h), after everything else.
  std::vector<std::pair<std::string, double>> disturbances;
};

struct RunPlan {
  std::string scenario;  // absolute path of the base scenario
  // Of the program's version and the texts of the scenario, its board, machine and calibration
  // files (config/content_hash.h): a changed input or another build is another plan, whose
  // runs are not these. (The seedling force model's file is not in it.)
  std::string inputs_hash;
  std::vector<PlannedRun> runs;
};

// An empty plan on the scenario file as it is now, for the program of version `made_by`.
// Throws config::ConfigError for a bad scenario.
RunPlan new_plan(const std::string& scenario_path, const std::string& made_by);

// The plan as JSON (plan.json), and back; read_plan throws std::runtime_error naming the file.
std::string plan_json(const RunPlan& plan);
RunPlan read_plan(const std::string& path);
// The base scenario with the run's settings.
Scenario planned_scenario(const Scenario& base, const PlannedRun& run);

// DIR/runs/00012: run 12's output set; complete when its manifest is there.
std::string run_dir(const std::string& plan_dir, std::size_t index);
bool run_complete(const std::string& plan_dir, std::size_t index);
// Runs run `index` of a plan in DIR on `base` (the plan's scenario, loaded and checked against
// the plan's key) and writes its summary.json whole or not at all.
void run_planned(const std::string& plan_dir, const Scenario& base, const PlannedRun& run,
                 std::size_t index);
// The plan's scenario, loaded; throws when the inputs or the program (`made_by`) are no longer
// the plan's.
Scenario plan_base(const std::string& plan_path, const RunPlan& plan, const std::string& made_by);
// Runs one run of the plan in DIR (the plan file's folder) and writes its summary.json whole
// or not at all; a complete run is left as it is. Throws on a bad plan or index, or when the
// inputs or the program (`made_by`) are no longer the plan's.
void execute_planned_run(const std::string& plan_path, std::size_t index,
                         const std::string& made_by);
// The summary a complete run wrote. Throws std::runtime_error naming the file.
Summary read_run_summary(const std::string& plan_dir, std::size_t index);

// Writes DIR/plan.json, or keeps the one there if it is the same plan. When DIR holds another
// plan (other inputs, another build, other settings) its runs are not these: with `replace`
// DIR's plan, runs and logs are removed first, else it throws naming DIR.
void place_plan(const std::string& plan_dir, const RunPlan& plan, bool replace);

}  // namespace planter::sim
