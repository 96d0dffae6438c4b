#include "apps/planter-sim/grip_benchmark.h"

#include <cstdio>
#include <iterator>
#include <sstream>

#include "apps/planter-sim/sweep.h"

namespace planter::sim {
namespace {
constexpr std::size_t kConstants = std::size(kClampForceCurve_N);
}  // namespace

void add_grip_benchmark_runs(RunPlan& plan, std::size_t draws) {
  for (std::size_t i = 0; i < draws; ++i) plan.runs[i].per_stem_grip = true;
  for (std::size_t i = 0; i < draws; ++i) {
    for (double f : kClampForceCurve_N) {
      PlannedRun r = plan.runs[i];
      r.per_stem_grip = false;
      r.clamp_setpoint_N = f;
      plan.runs.push_back(r);
    }
  }
}

GripVerdict judge_grip(const Summary& per_stem, const std::vector<Summary>& constants) {
  GripVerdict v;
  bool found = false;
  for (std::size_t c = 0; c < constants.size(); ++c) {
    if (constants[c].uprightness_pct < per_stem.uprightness_pct) continue;
    if (!found || constants[c].damage_pct < constants[v.best].damage_pct) v.best = c;
    found = true;
  }
  if (!found) {
    for (std::size_t c = 1; c < constants.size(); ++c)
      if (constants[c].uprightness_pct > constants[v.best].uprightness_pct) v.best = c;
  }
  const Summary& best = constants[v.best];
  v.no_damage = best.seedlings_damaged == 0 && per_stem.seedlings_damaged == 0;
  v.halved = !v.no_damage && per_stem.damage_pct <= 0.5 * best.damage_pct;
  return v;
}

GripBenchmark grip_benchmark(const std::vector<Summary>& all, std::size_t draws) {
  GripBenchmark b;
  std::ostringstream csv;
  csv << "run,per_stem_uprightness_pct,per_stem_damage_pct,best_constant_N,"
         "best_uprightness_pct,best_damage_pct,halved\n";
  std::size_t halved = 0, no_damage = 0;
  for (std::size_t i = 0; i < draws; ++i) {
    const auto first = all.begin() + static_cast<std::ptrdiff_t>(draws + i * kConstants);
    const std::vector<Summary> constants(first, first + static_cast<std::ptrdiff_t>(kConstants));
    const GripVerdict v = judge_grip(all[i], constants);
    halved += v.halved ? 1 : 0;
    no_damage += v.no_damage ? 1 : 0;
    const Summary& best = constants[v.best];
    csv << i + 1 << ',' << all[i].uprightness_pct << ',' << all[i].damage_pct << ','
        << kClampForceCurve_N[v.best] << ',' << best.uprightness_pct << ',' << best.damage_pct
        << ','
        << (v.no_damage ? "no damage"
            : v.halved  ? "yes"
                        : "no")
        << '\n';
  }
  b.csv = csv.str();
  const std::size_t compared = draws - no_damage;
  const double share_pct =
      compared > 0 ? 100.0 * static_cast<double>(halved) / static_cast<double>(compared) : 0.0;
  b.json = {{"draws", draws},   {"compared", compared},    {"no_damage_either", no_damage},
            {"halved", halved}, {"halved_pct", share_pct}, {"goal_pct", 90.0}};
  char line[256];
  std::snprintf(line, sizeof line,
                "per-stem grip: damage at most half the best constant force's, at equal or "
                "better uprightness, in %zu of %zu draws (%.0f %%; %zu with no damage either "
                "way); goal 90 %%",
                halved, compared, share_pct, no_damage);
  b.line = line;
  return b;
}

}  // namespace planter::sim
