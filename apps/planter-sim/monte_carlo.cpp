#include "apps/planter-sim/monte_carlo.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "apps/planter-sim/grip_benchmark.h"
#include "apps/planter-sim/latin_hypercube.h"
#include "apps/planter-sim/run_figures.h"
#include "apps/planter-sim/sweep.h"
#include "apps/version/version.h"
#include "config/output_set.h"
#include "sim/plant/model_values.h"
#include "sim/runner/run_plan.h"
#include "sim/runner/scenario.h"

namespace planter::sim {
namespace {

struct Distribution {
  double mean = 0, sd = 0, standard_error = 0, p5 = 0, median = 0, p95 = 0;
};

Distribution distribution_of(std::vector<double> v) {
  Distribution d;
  const auto n = static_cast<double>(v.size());
  d.mean = std::accumulate(v.begin(), v.end(), 0.0) / n;
  for (double x : v) d.sd += (x - d.mean) * (x - d.mean);
  d.sd = v.size() > 1 ? std::sqrt(d.sd / (n - 1.0)) : 0.0;
  d.standard_error = d.sd / std::sqrt(n);
  std::sort(v.begin(), v.end());
  // Quantiles by linear interpolation between order statistics (Hyndman & Fan's type 7).
  const auto at = [&](double p) {
    const double h = p * (n - 1.0);
    const auto lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (h - static_cast<double>(lo)) * (v[hi] - v[lo]);
  };
  d.p5 = at(0.05);
  d.median = at(0.5);
  d.p95 = at(0.95);
  return d;
}

// "5-15" -> {5, 15}, within the scenario keys' range; a clear message otherwise.
std::pair<double, double> stems_range_mm(const std::string& text) {
  double lo = 0, hi = 0;
  char dash = 0;
  std::istringstream in(text);
  if (!(in >> lo >> dash >> hi) || dash != '-' || !in.eof() || !(lo >= 1.0) || !(hi <= 30.0) ||
      !(lo <= hi))
    throw std::runtime_error("--stems-mm: '" + text +
                             "' is not MIN-MAX in mm with 1 <= MIN <= MAX <= 30 (e.g. 5-15)");
  return {lo, hi};
}

}  // namespace

int run_monte_carlo(const std::string& scenario_path, const std::string& out_dir,
                    const MonteCarloOptions& o) {
  const Scenario base = load_scenario(scenario_path);
  if (const std::string why = executor_refusal(o.executor); !why.empty())
    throw std::runtime_error(why);
  config::OutputSet out(out_dir, "planter-sim montecarlo", o.force);
  const auto values = model_values();
  const std::size_t k = values.size();
  const auto n = static_cast<std::size_t>(o.runs);

  // Seeded by the scenario's seed.
  std::mt19937_64 rng(base.seed);
  const std::vector<std::vector<double>> coded = latin_hypercube(n, k, rng);
  RunPlan plan = new_plan(scenario_path, apps::version());
  for (std::size_t i = 0; i < n; ++i) {
    PlannedRun run;
    run.distance_m = o.distance_m;
    run.seed = base.seed + i;
    for (std::size_t f = 0; f < k; ++f)
      run.values.emplace_back(values[f].key,
                              values[f].low + coded[i][f] * (values[f].high - values[f].low));
    plan.runs.push_back(run);
  }
  if (!o.stems_mm.empty()) {
    const auto [lo, hi] = stems_range_mm(o.stems_mm);
    for (PlannedRun& run : plan.runs)
      run.disturbances = {{"seedlings.diameter_min_mm", lo}, {"seedlings.diameter_max_mm", hi}};
  }
  if (o.grip) add_grip_benchmark_runs(plan, n);
  std::fprintf(stderr,
               "planter-sim montecarlo: %zu draws of %.0f m (a Latin hypercube over %zu values, "
               "one seed a draw)%s\n",
               n, o.distance_m, k,
               o.grip ? ", each also at every constant force of the sweep's trade-off" : "");
  const std::vector<Summary> all =
      execute_plan(runs_folder(out_dir) + "/runs", plan, executor_for(o.executor, o.jobs, o.force),
                   "montecarlo");

  std::array<std::vector<double>, kRunFigureCount> figures;
  std::ostringstream csv;
  csv << "run,seed";
  for (const ModelValue& v : values) csv << ',' << v.key;
  for (const RunFigure& f : kRunFigures) csv << ',' << f.column;
  csv << ",seedlings_planted\n";
  for (std::size_t i = 0; i < n; ++i) {
    const auto at_run = run_figures(all[i]);
    const Scenario at = planned_scenario(base, plan.runs[i]);
    csv << i + 1 << ',' << plan.runs[i].seed;
    for (const ModelValue& v : values) csv << ',' << v.value(at.plant);
    for (std::size_t q = 0; q < kRunFigureCount; ++q) {
      csv << ',' << at_run[q];
      figures[q].push_back(at_run[q]);
    }
    csv << ',' << all[i].seedlings_planted << '\n';
  }
  nlohmann::json j;
  j["scenario"] = base.name;
  j["method"] = "Latin hypercube over the model values' plausible ranges, one seed a run";
  j["runs"] = n;
  j["distance_m_per_run"] = o.distance_m;
  for (const ModelValue& v : values)
    j["values"].push_back(
        {{"key", v.key}, {"origin", origin_name(v.origin)}, {"range", {v.low, v.high}}});
  std::array<Distribution, kRunFigureCount> dist;
  for (std::size_t q = 0; q < kRunFigureCount; ++q) {
    dist[q] = distribution_of(figures[q]);
    j["figures"][kRunFigures[q].name] = {{"unit", kRunFigures[q].unit},
                                         {"mean", dist[q].mean},
                                         {"sd", dist[q].sd},
                                         {"standard_error", dist[q].standard_error},
                                         {"p5", dist[q].p5},
                                         {"median", dist[q].median},
                                         {"p95", dist[q].p95}};
  }
  j["paper"] = {{"uprightness_pct", kPaperCentreUprightness_pct},
                {"damage_pct", kPaperCentreDamage_pct}};
  GripBenchmark grip;
  if (o.grip) {
    grip = grip_benchmark(all, n);
    j["grip_benchmark"] = grip.json;
    out.write("grip_benchmark.csv", grip.csv);
  }
  out.write("montecarlo.csv", csv.str());
  out.write("montecarlo.json", j.dump(2) + "\n");
  out.commit();

  std::printf("%zu runs of %.0f m: a Latin hypercube over %zu values, one seed a run\n", n,
              o.distance_m, k);
  for (std::size_t q = 0; q < kRunFigureCount; ++q)
    std::printf("%-22s mean %.4g +- %.2g %s (standard error), 5-95 %% of runs %.4g-%.4g\n",
                kRunFigures[q].name, dist[q].mean, dist[q].standard_error, kRunFigures[q].unit,
                dist[q].p5, dist[q].p95);
  std::printf("wrote %s/{montecarlo.csv,montecarlo.json}\n", out_dir.c_str());
  std::printf(
      "across what is not known (5-95 %% of runs): uprightness %.1f-%.1f %%, damage %.2f-%.2f %%; "
      "paper: %.1f %% and %.0f %%, a comparison and not a target\n",
      dist[0].p5, dist[0].p95, dist[1].p5, dist[1].p95, kPaperCentreUprightness_pct,
      kPaperCentreDamage_pct);
  if (o.grip) std::printf("%s\n%s\n", grip.bound_line.c_str(), grip.line.c_str());
  return 0;
}

}  // namespace planter::sim
