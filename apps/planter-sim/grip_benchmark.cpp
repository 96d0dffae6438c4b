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
  for (std::size_t i = 0; i < draws; ++i) {
    PlannedRun r = plan.runs[i];
    r.per_stem_grip = false;
    r.clamp_told_each_stem = true;
    plan.runs.push_back(r);
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

namespace {
const char* verdict_word(const GripVerdict& v) {
  return v.no_damage ? "no damage" : v.halved ? "yes" : "no";
}

// One arm's tally over the draws: halved, and with no damage either way.
struct Tally {
  std::size_t halved = 0, no_damage = 0;
  void add(const GripVerdict& v) {
    halved += v.halved ? 1 : 0;
    no_damage += v.no_damage ? 1 : 0;
  }
  [[nodiscard]] nlohmann::json json(std::size_t draws) const {
    const std::size_t compared = draws - no_damage;
    const double pct =
        compared > 0 ? 100.0 * static_cast<double>(halved) / static_cast<double>(compared) : 0.0;
    return {{"draws", draws},   {"compared", compared}, {"no_damage_either", no_damage},
            {"halved", halved}, {"halved_pct", pct},    {"goal_pct", 90.0}};
  }
  [[nodiscard]] std::string text(std::size_t draws) const {
    const std::size_t compared = draws - no_damage;
    const double pct =
        compared > 0 ? 100.0 * static_cast<double>(halved) / static_cast<double>(compared) : 0.0;
    char line[160];
    std::snprintf(line, sizeof line, "in %zu of %zu draws (%.0f %%; %zu with no damage either way)",
                  halved, compared, pct, no_damage);
    return line;
  }
};
}  // namespace

GripBenchmark grip_benchmark(const std::vector<Summary>& all, std::size_t draws) {
  GripBenchmark b;
  std::ostringstream csv;
  csv << "run,per_stem_uprightness_pct,per_stem_damage_pct,best_constant_N,"
         "best_uprightness_pct,best_damage_pct,halved,told_uprightness_pct,told_damage_pct,"
         "told_best_constant_N,told_halved\n";
  Tally per_stem, told;
  const std::size_t told_first = draws + draws * kConstants;
  for (std::size_t i = 0; i < draws; ++i) {
    const auto first = all.begin() + static_cast<std::ptrdiff_t>(draws + i * kConstants);
    const std::vector<Summary> constants(first, first + static_cast<std::ptrdiff_t>(kConstants));
    const GripVerdict v = judge_grip(all[i], constants);
    const Summary& bound = all[told_first + i];
    const GripVerdict t = judge_grip(bound, constants);
    per_stem.add(v);
    told.add(t);
    const Summary& best = constants[v.best];
    csv << i + 1 << ',' << all[i].uprightness_pct << ',' << all[i].damage_pct << ','
        << kClampForceCurve_N[v.best] << ',' << best.uprightness_pct << ',' << best.damage_pct
        << ',' << verdict_word(v) << ',' << bound.uprightness_pct << ',' << bound.damage_pct << ','
        << kClampForceCurve_N[t.best] << ',' << verdict_word(t) << '\n';
  }
  b.csv = csv.str();
  b.json = per_stem.json(draws);
  b.json["told_each_stem"] = told.json(draws);
  b.bound_line =
      "bound, a clamp told each stem's true peak (no sensor on the machine can): "
      "damage at most half the best constant force's " +
      told.text(draws);
  b.line =
      "per-stem grip: damage at most half the best constant force's, at equal or better "
      "uprightness, " +
      per_stem.text(draws) + "; goal 90 %";
  return b;
}

}  // namespace planter::sim
