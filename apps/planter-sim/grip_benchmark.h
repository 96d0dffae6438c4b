#pragma once
// The clamp that grips each stem under its own ceiling against one constant force (issue 50):
// for each montecarlo draw of the model values, the per-stem clamp at the machine's set-point
// and each constant force of the sweep's trade-off, all on the draw's values and seed (the same
// seedlings). Judged as the issue asks: the per-stem clamp's damage at most half the best
// constant force's, where the best is the least damage among the constant forces with at least
// the per-stem clamp's uprightness (or, if none has, the most upright).
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/runner/run_plan.h"
#include "sim/runner/summary.h"

namespace planter::sim {

// The plan's first `draws` runs are the draws; sets them per stem and appends each constant
// force for each draw (draw-major), then each draw with the clamp told each stem's true peak (a
// bound: Scenario::clamp_told_each_stem).
void add_grip_benchmark_runs(RunPlan& plan, std::size_t draws);

struct GripVerdict {
  std::size_t best = 0;    // index into the constant forces
  bool halved = false;     // per stem: damage <= half the best's
  bool no_damage = false;  // neither damaged a seedling: no comparison to make
};
GripVerdict judge_grip(const Summary& per_stem, const std::vector<Summary>& constants);

// The verdicts of every draw from the executed plan's summaries: CSV rows, JSON, and the line
// printed last ("per-stem grip: damage halved ... in K of N draws").
struct GripBenchmark {
  std::string csv;
  nlohmann::json json;
  std::string bound_line;  // the same verdict for the clamp told each stem's true peak
  std::string line;
};
GripBenchmark grip_benchmark(const std::vector<Summary>& all, std::size_t draws);

}  // namespace planter::sim
