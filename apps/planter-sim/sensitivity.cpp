#include "apps/planter-sim/sensitivity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

#include "apps/planter-sim/run_figures.h"
#include "apps/planter-sim/sweep.h"
#include "apps/version/version.h"
#include "config/output_set.h"
#include "report/html_text.h"
#include "sim/plant/model_values.h"
#include "sim/runner/run_plan.h"
#include "sim/runner/scenario.h"

namespace planter::sim {
namespace {

// Morris's grid: 4 levels on [0, 1], a step of 2/3 (p / (2 (p - 1))), so each base level is 0
// or 1/3 and the step stays inside the range.
constexpr int kLevels = 4;
constexpr double kStep = kLevels / (2.0 * (kLevels - 1));

struct Response {
  const char* name;
  const char* unit;
};
// The figures at the operating point, then (with --optimum) the design's optimum.
const Response kResponses[] = {{"uprightness", "%"},
                               {"damage", "%"},
                               {"turned in the clamp", "%"},
                               {"optimum contact area", "mm^2"},
                               {"optimum disc speed", "rad/s"},
                               {"optimum depth", "mm"}};
constexpr std::size_t kResponseCount = sizeof kResponses / sizeof kResponses[0];
constexpr std::size_t kPointResponses = 3;
// The terms of the design's quadratic (doe/doe.h's names).
constexpr const char* kQuadraticTerms[] = {"A", "B", "C", "AB", "AC", "BC", "A^2", "B^2", "C^2"};
// How far a finding may move across the plausible ranges (5-95 % of the points) and still hold:
// 5 points of a figure, a fifth of the design's span for an optimum's coordinate.
constexpr double kFigureHoldsWithin_pts = 5.0, kOptimumSpanParts = 5.0;
double holds_within(std::size_t q) {
  return q < kPointResponses
             ? kFigureHoldsWithin_pts
             : design_span(static_cast<int>(q - kPointResponses)) / kOptimumSpanParts;
}
using Figures = std::array<double, kResponseCount>;

Figures figures_of(const Summary& s) {
  Figures f{};
  const auto at_point = run_figures(s);
  std::copy(at_point.begin(), at_point.end(), f.begin());
  return f;
}

struct Effect {
  double mu_star = 0, mu = 0, sigma = 0;  // of the elementary effects, per the whole range
};

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

int run_sensitivity(const std::string& scenario_path, const std::string& out_dir,
                    const SensitivityOptions& o) {
  const Scenario base = load_scenario(scenario_path);
  if (const std::string why = executor_refusal(o.executor); !why.empty())
    throw std::runtime_error(why);
  config::OutputSet out(out_dir, "planter-sim sensitivity", o.force);
  const auto values = model_values();
  const std::size_t k = values.size();
  const int r = o.trajectories;
  const int jobs =
      o.jobs > 0 ? o.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));

  // The design: per trajectory a base point on the grid, then one factor at a time by +step,
  // in a random order.
  std::mt19937_64 rng(base.seed);
  std::vector<std::vector<double>> points;  // coded, [0, 1]
  std::vector<std::size_t> moved;           // factor moved to reach point i (k: the base)
  std::vector<int> trajectory_of;
  for (int t = 0; t < r; ++t) {
    std::vector<double> x(k);
    for (double& xi : x) xi = static_cast<double>(rng() % 2) / (kLevels - 1);
    std::vector<std::size_t> order(k);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    points.push_back(x);
    moved.push_back(k);
    trajectory_of.push_back(t);
    for (std::size_t f : order) {
      x[f] += kStep;
      points.push_back(x);
      moved.push_back(f);
      trajectory_of.push_back(t);
    }
  }
  RunPlan plan = new_plan(scenario_path, apps::version());
  for (std::size_t i = 0; i < points.size(); ++i) {
    PlannedRun run;
    run.distance_m = o.distance_m;
    run.seed = base.seed + static_cast<std::uint64_t>(trajectory_of[i]);
    for (std::size_t f = 0; f < k; ++f)
      run.values.emplace_back(values[f].key,
                              values[f].low + points[i][f] * (values[f].high - values[f].low));
    plan.runs.push_back(run);
    // With --optimum each point also runs the paper's design (one replicate) around it.
    if (o.optimum)
      for (const PlannedRun& d : design_runs(base, run)) plan.runs.push_back(d);
  }
  const std::size_t per_point = o.optimum ? 1 + design_runs(base, PlannedRun{}).size() : 1;
  std::fprintf(stderr,
               "planter-sim sensitivity: %zu runs of %.0f m (%zu points: %d trajectories x (%zu "
               "values + 1)), %d jobs\n",
               plan.runs.size(), o.distance_m, points.size(), r, k, jobs);
  const std::vector<Summary> all =
      execute_plan(runs_folder(out_dir) + "/points", plan,
                   executor_for(o.executor, o.jobs, o.force), "sensitivity");
  const std::size_t responses = o.optimum ? kResponseCount : kPointResponses;
  std::vector<Figures> y;
  std::map<std::string, int> significant_at;  // term -> points where it is significant
  for (std::size_t i = 0; i < points.size(); ++i) {
    Figures f = figures_of(all[i * per_point]);
    if (o.optimum) {
      const auto first = all.begin() + static_cast<std::ptrdiff_t>(i * per_point + 1);
      const DesignOptimum best = design_optimum(
          std::vector<Summary>(first, first + static_cast<std::ptrdiff_t>(per_point - 1)));
      f[3] = best.contact_area_mm2;
      f[4] = best.disc_speed_radps;
      f[5] = best.depth_mm;
      for (const std::string& t : best.significant_terms) ++significant_at[t];
    }
    y.push_back(f);
  }

  // Elementary effects: the change of a response over the whole range, (y1 - y0) / step.
  std::vector<std::array<Effect, kResponseCount>> effects(k);
  std::vector<std::array<std::vector<double>, kResponseCount>> ee(k);
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (moved[i] == k) continue;
    for (std::size_t q = 0; q < responses; ++q) {
      const double d = (y[i][q] - y[i - 1][q]) / kStep;
      ee[moved[i]][q].push_back(d);
    }
  }
  for (std::size_t f = 0; f < k; ++f) {
    for (std::size_t q = 0; q < responses; ++q) {
      const std::vector<double>& v = ee[f][q];
      Effect& e = effects[f][q];
      for (double d : v) {
        e.mu += d / static_cast<double>(v.size());
        e.mu_star += std::abs(d) / static_cast<double>(v.size());
      }
      for (double d : v) e.sigma += (d - e.mu) * (d - e.mu);
      e.sigma = v.size() > 1 ? std::sqrt(e.sigma / static_cast<double>(v.size() - 1)) : 0.0;
    }
  }
  // Ranks by mu* of each response (1: most influential).
  std::vector<std::array<int, kResponseCount>> rank(k);
  for (std::size_t q = 0; q < responses; ++q) {
    std::vector<std::size_t> by(k);
    std::iota(by.begin(), by.end(), 0);
    std::sort(by.begin(), by.end(), [&](std::size_t a, std::size_t b) {
      return effects[a][q].mu_star > effects[b][q].mu_star;
    });
    for (std::size_t i = 0; i < k; ++i) rank[by[i]][q] = static_cast<int>(i) + 1;
  }
  // The figures' spread over every point, across the plausible ranges (min, 5 %, median,
  // 95 %, max), and whether each holds.
  std::vector<std::array<double, 5>> spread(responses);
  std::vector<bool> holds(responses);  // per figure
  for (std::size_t q = 0; q < responses; ++q) {
    std::vector<double> v;
    for (const Figures& f : y) v.push_back(f[q]);
    std::sort(v.begin(), v.end());
    const auto at = [&](double p) {
      return v[static_cast<std::size_t>(std::lround(p * static_cast<double>(v.size() - 1)))];
    };
    spread[q] = {v.front(), at(0.05), at(0.5), at(0.95), v.back()};
    holds[q] = spread[q][3] - spread[q][1] <= holds_within(q);
  }

  std::ostringstream csv;
  csv << "run,trajectory,moved";
  for (const ModelValue& v : values) csv << ',' << v.key;
  csv << ",uprightness_pct,damage_pct,turned_in_clamp_pct,seedlings_planted,seedlings_lodged,"
         "seedlings_fell_in_carry";
  if (o.optimum) csv << ",optimum_contact_area_mm2,optimum_disc_speed_radps,optimum_depth_mm";
  csv << '\n';
  for (std::size_t i = 0; i < points.size(); ++i) {
    csv << i + 1 << ',' << trajectory_of[i] + 1 << ','
        << (moved[i] == k ? "base" : values[moved[i]].key);
    const Summary& run = all[i * per_point];
    const Scenario at = planned_scenario(base, plan.runs[i * per_point]);
    for (const ModelValue& v : values) csv << ',' << v.value(at.plant);
    csv << ',' << y[i][0] << ',' << y[i][1] << ',' << y[i][2] << ',' << run.seedlings_planted << ','
        << run.seedlings_lodged << ',' << run.seedlings_fell_in_carry;
    if (o.optimum) csv << ',' << y[i][3] << ',' << y[i][4] << ',' << y[i][5];
    csv << '\n';
  }
  nlohmann::json j;
  j["scenario"] = base.name;
  j["method"] = "Morris elementary effects, 4 levels, step 2/3";
  j["trajectories"] = r;
  j["runs"] = plan.runs.size();
  j["points"] = points.size();
  j["distance_m_per_run"] = o.distance_m;
  for (std::size_t f = 0; f < k; ++f) {
    nlohmann::json v;
    v["key"] = values[f].key;
    v["origin"] = origin_name(values[f].origin);
    v["range"] = {values[f].low, values[f].high};
    v["in_use"] = values[f].value(base.plant);
    for (std::size_t q = 0; q < responses; ++q)
      v[kResponses[q].name] = {{"mu_star", effects[f][q].mu_star},
                               {"mu", effects[f][q].mu},
                               {"sigma", effects[f][q].sigma},
                               {"rank", rank[f][q]}};
    j["values"].push_back(v);
  }
  for (std::size_t q = 0; q < responses; ++q) {
    const auto& s = spread[q];
    j["spread"][kResponses[q].name] = {{"min", s[0]},
                                       {"p5", s[1]},
                                       {"median", s[2]},
                                       {"p95", s[3]},
                                       {"max", s[4]},
                                       {"holds_within", holds_within(q)},
                                       {"holds", static_cast<bool>(holds[q])}};
  }
  // How often each term of uprightness's quadratic is significant across the points: a term
  // the paper lists holds when it is significant at 90 % of them, one it does not when at 10 %
  // at most (the same rule as the figures'). One replicate per design point: 5 residual df.
  std::vector<std::string> terms_hold, terms_fail;
  if (o.optimum) {
    for (const std::string t : kQuadraticTerms) {
      const double share =
          static_cast<double>(significant_at[t]) / static_cast<double>(points.size());
      const auto& paper = paper_significant_terms();
      const bool in_paper = std::find(paper.begin(), paper.end(), t) != paper.end();
      const bool verdict_holds = in_paper ? share >= 0.9 : share <= 0.1;
      j["significant_terms"][t] = {
          {"share_of_points", share}, {"in_paper", in_paper}, {"paper_holds", verdict_holds}};
      (verdict_holds ? terms_hold : terms_fail).push_back(t);
    }
    j["paper_terms_holding"] = terms_hold;
    j["paper_terms_not_holding"] = terms_fail;
  }
  j["paper"] = {{"uprightness_pct", kPaperCentreUprightness_pct},
                {"damage_pct", kPaperCentreDamage_pct},
                {"optimum_contact_area_mm2", kPaperOptimum[0]},
                {"optimum_disc_speed_radps", kPaperOptimum[1]},
                {"optimum_depth_mm", kPaperOptimum[2]}};
  const std::string paper_optimum =
      optimum_text(kPaperOptimum[0], kPaperOptimum[1], kPaperOptimum[2]);

  std::vector<std::size_t> order(k);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return rank[a][0] < rank[b][0]; });
  std::ostringstream html;
  html << "<!doctype html><html><head>" << report::kReportHead
       << "<title>Sensitivity: " << report::html_escape(base.name) << "</title>"
       << report::kTablePageStyle
       << "</head><body><h1>Which model "
          "values the conclusions rest on</h1><p>Morris's elementary effects: "
       << r << " trajectories over " << k << " values, " << plan.runs.size() << " runs of "
       << o.distance_m
       << " m at the scenario's operating point. mu* is the mean absolute change of a figure when "
          "the value crosses its whole plausible range (in points); sigma its spread "
          "(interactions or non-linearity).</p><table><tr><th>value</th><th>origin</th><th>range"
          "</th>";
  for (std::size_t q = 0; q < responses; ++q)
    html << "<th>" << kResponses[q].name << " mu* [" << kResponses[q].unit
         << "]</th><th>sigma</th><th>rank</th>";
  html << "</tr>";
  for (std::size_t f : order) {
    html << "<tr><td style='text-align:left'>" << values[f].key << "</td><td>"
         << origin_name(values[f].origin) << "</td><td>" << fmt("%.4g", values[f].low) << " - "
         << fmt("%.4g", values[f].high) << "</td>";
    for (std::size_t q = 0; q < responses; ++q)
      html << "<td>" << fmt("%.3g", effects[f][q].mu_star) << "</td><td>"
           << fmt("%.3g", effects[f][q].sigma) << "</td><td>" << rank[f][q] << "</td>";
    html << "</tr>";
  }
  html << "</table><h2>The figures across the plausible ranges</h2><ul>";
  for (std::size_t q = 0; q < responses; ++q) {
    const auto& s = spread[q];
    html << "<li>" << kResponses[q].name << ": " << fmt("%.4g", s[1]) << " - " << fmt("%.4g", s[3])
         << " " << kResponses[q].unit << " (5-95 % of the points; median " << fmt("%.4g", s[2])
         << ")</li>";
  }
  html << "</ul><p>The paper: " << fmt("%.1f", kPaperCentreUprightness_pct) << " % upright and "
       << fmt("%.0f", kPaperCentreDamage_pct) << " % damaged at its optimum of " << paper_optimum
       << ", a comparison and not a target.</p><h2>The model's values</h2>"
       << model_values_html(base.plant) << "</body></html>";

  out.write("sensitivity.csv", csv.str());
  out.write("sensitivity.json", j.dump(2) + "\n");
  out.write("report.html", html.str());
  out.commit();

  std::printf("%zu points, %zu runs of %.0f m: Morris, %d trajectories over %zu values\n",
              points.size(), plan.runs.size(), o.distance_m, r, k);
  std::printf("%-40s %-10s %8s %5s %8s %5s %8s %5s\n", "value (by uprightness mu*)", "origin",
              "upright", "rank", "damage", "rank", "turned", "rank");
  for (std::size_t f : order)
    std::printf("%-40s %-10s %8.2f %5d %8.2f %5d %8.2f %5d\n", values[f].key,
                origin_name(values[f].origin), effects[f][0].mu_star, rank[f][0],
                effects[f][1].mu_star, rank[f][1], effects[f][2].mu_star, rank[f][2]);
  std::printf("wrote %s/{sensitivity.csv,sensitivity.json,report.html}\n", out_dir.c_str());
  for (std::size_t q = 0; q < responses; ++q)
    std::printf("%-22s %s across the ranges: %.4g-%.4g %s (holds if within %.3g)\n",
                kResponses[q].name, holds[q] ? "holds  " : "DOES NOT HOLD", spread[q][1],
                spread[q][3], kResponses[q].unit, holds_within(q));
  if (o.optimum) {
    std::printf("terms of uprightness significant (paper's:");
    for (const std::string& t : paper_significant_terms()) std::printf(" %s", t.c_str());
    std::printf("), share of points:");
    for (const std::string t : kQuadraticTerms)
      std::printf(" %s %.0f%%", t.c_str(),
                  100.0 * significant_at[t] / static_cast<double>(points.size()));
    std::printf("; the paper's verdict holds for %zu of %zu terms\n", terms_hold.size(),
                std::size(kQuadraticTerms));
    const auto &area = spread[3], &speed = spread[4], &depth = spread[5];
    std::printf(
        "optimum across the plausible ranges (5-95 %% of points): %.0f-%.0f mm^2, %.3f-%.3f rad/s, "
        "%.0f-%.0f mm; paper: %s\n",
        area[1], area[3], speed[1], speed[3], depth[1], depth[3], paper_optimum.c_str());
  }
  std::printf(
      "across the plausible ranges (5-95 %% of runs): uprightness %.1f-%.1f %%, damage %.2f-%.2f "
      "%%; paper: %.1f %% and %.0f %%\n",
      spread[0][1], spread[0][3], spread[1][1], spread[1][3], kPaperCentreUprightness_pct,
      kPaperCentreDamage_pct);
  return 0;
}

}  // namespace planter::sim
