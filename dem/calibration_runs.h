#pragma once
// The calibration's runs (calibration.h), each kept in DIR/runs under the hash of its
// parameters: KEY.toml, the parameters as a --params file, written before the run; KEY.json,
// the result, written whole after it. A run always starts from its KEY.toml, in this process
// or as `planter-dem plan-run PLAN INDEX` (a Slurm task, plan/executor.h), so where it ran
// does not change its result. A stage's runs not yet kept are a plan: DIR/plans/STAGE/plan.json.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "dem/compression_test.h"

namespace planter::dem {

// The run's key: a hash of the physics' revision and the parameters as written.
std::string run_key(const CompressionSetup& s);

// The result kept for `s` in `runs_dir`; none when it is not there, torn, or from other
// parameters (then the run is run again).
std::optional<CompressionResult> kept_result(const std::string& runs_dir,
                                             const CompressionSetup& s);

// Writes KEY.toml for `s` (kept if already there) and returns the key. Throws
// std::runtime_error when it cannot be written.
std::string place_run(const std::string& runs_dir, const CompressionSetup& s);

// Runs the run `key` of `runs_dir` from its KEY.toml and writes KEY.json whole; returns its
// result. Throws config::ConfigError for a bad KEY.toml, std::runtime_error for an unwritable
// result or a KEY.toml whose parameters are not the key's.
CompressionResult run_kept(const std::string& runs_dir, const std::string& key);

// A stage's plan (DIR/plans/STAGE/plan.json): the runs' folder and the keys, index by index.
void write_stage_plan(const std::string& path, const std::string& runs_dir,
                      const std::vector<std::string>& keys);
// `planter-dem plan-run PLAN INDEX`: runs that run of the plan (nothing when it is kept
// already). Throws config::ConfigError naming the plan for a bad plan or index.
void execute_stage_run(const std::string& plan_path, std::size_t index);

}  // namespace planter::dem
