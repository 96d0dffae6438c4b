#include "apps/planter-sim/sensitivity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <random>
#include <span>
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

// One Morris study: the design, its runs, what they show and the outputs, one step a method.
class SensitivityStudy {
 public:
  SensitivityStudy(const std::string& scenario_path, const SensitivityOptions& o)
      : path_(scenario_path),
        o_(o),
        base_(load_scenario(scenario_path)),
        values_(model_values()),
        k_(values_.size()),
        responses_(o.optimum ? kResponseCount : kPointResponses) {}

  void run(const std::string& out_dir) {
    design();
    plan_runs();
    execute(out_dir);
    read_figures();
    elementary_effects();
    rank_by_mu_star();
    spread_across_ranges();
  }

  void write(config::OutputSet& out) const {
    out.write("sensitivity.csv", csv());
    out.write("sensitivity.json", json().dump(2) + "\n");
    out.write("report.html", html());
    out.commit();
  }

  void print(const std::string& out_dir) const;

 private:
  // Per trajectory a base point on the grid, then one factor at a time by +step, in a random
  // order.
  void design() {
    std::mt19937_64 rng(base_.seed);
    for (int t = 0; t < o_.trajectories; ++t) {
      std::vector<double> x(k_);
      for (double& xi : x) xi = static_cast<double>(rng() % 2) / (kLevels - 1);
      std::vector<std::size_t> order(k_);
      std::iota(order.begin(), order.end(), 0);
      std::shuffle(order.begin(), order.end(), rng);
      add_point(x, k_, t);
      for (std::size_t f : order) {
        x[f] += kStep;
        add_point(x, f, t);
      }
    }
  }

  void add_point(const std::vector<double>& x, std::size_t moved, int trajectory) {
    points_.push_back(x);
    moved_.push_back(moved);
    trajectory_of_.push_back(trajectory);
  }

  // Each point's run; with --optimum each point also runs the paper's design (one replicate)
  // around it.
  void plan_runs() {
    plan_ = new_plan(path_, apps::version());
    for (std::size_t i = 0; i < points_.size(); ++i) {
      PlannedRun run;
      run.distance_m = o_.distance_m;
      run.seed = base_.seed + static_cast<std::uint64_t>(trajectory_of_[i]);
      for (std::size_t f = 0; f < k_; ++f)
        run.values.emplace_back(
            values_[f].key, values_[f].low + points_[i][f] * (values_[f].high - values_[f].low));
      plan_.runs.push_back(run);
      if (o_.optimum)
        for (const PlannedRun& d : design_runs(base_, run)) plan_.runs.push_back(d);
    }
    per_point_ = o_.optimum ? 1 + design_runs(base_, PlannedRun{}).size() : 1;
  }

  void execute(const std::string& out_dir) {
    const int jobs =
        o_.jobs > 0 ? o_.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    std::fprintf(stderr,
                 "planter-sim sensitivity: %zu runs of %.0f m (%zu points: %d trajectories x (%zu "
                 "values + 1)), %d jobs\n",
                 plan_.runs.size(), o_.distance_m, points_.size(), o_.trajectories, k_, jobs);
    all_ = execute_plan(runs_folder(out_dir) + "/points", plan_,
                        executor_for(o_.executor, o_.jobs, o_.force), "sensitivity");
  }

  // The figures at each point; with --optimum, the design's optimum around it and the terms of
  // its quadratic that are significant there.
  void read_figures() {
    for (std::size_t i = 0; i < points_.size(); ++i) {
      Figures f = figures_of(all_[i * per_point_]);
      if (o_.optimum) {
        const auto first = all_.begin() + static_cast<std::ptrdiff_t>(i * per_point_ + 1);
        const DesignOptimum best = design_optimum(
            std::vector<Summary>(first, first + static_cast<std::ptrdiff_t>(per_point_ - 1)));
        f[3] = best.contact_area_mm2;
        f[4] = best.disc_speed_radps;
        f[5] = best.depth_mm;
        for (const std::string& t : best.significant_terms) ++significant_at_[t];
      }
      y_.push_back(f);
    }
  }

  // Elementary effects: the change of a response over the whole range, (y1 - y0) / step.
  void elementary_effects() {
    std::vector<std::array<std::vector<double>, kResponseCount>> ee(k_);
    for (std::size_t i = 1; i < points_.size(); ++i) {
      if (moved_[i] == k_) continue;
      for (std::size_t q = 0; q < responses_; ++q)
        ee[moved_[i]][q].push_back((y_[i][q] - y_[i - 1][q]) / kStep);
    }
    effects_.resize(k_);
    for (std::size_t f = 0; f < k_; ++f)
      for (std::size_t q = 0; q < responses_; ++q) {
        const std::vector<double>& v = ee[f][q];
        Effect& e = effects_[f][q];
        for (double d : v) {
          e.mu += d / static_cast<double>(v.size());
          e.mu_star += std::abs(d) / static_cast<double>(v.size());
        }
        for (double d : v) e.sigma += (d - e.mu) * (d - e.mu);
        e.sigma = v.size() > 1 ? std::sqrt(e.sigma / static_cast<double>(v.size() - 1)) : 0.0;
      }
  }

  // Ranks by mu* of each response (1: most influential); the values in uprightness's order.
  void rank_by_mu_star() {
    rank_.resize(k_);
    for (std::size_t q = 0; q < responses_; ++q) {
      std::vector<std::size_t> by(k_);
      std::iota(by.begin(), by.end(), 0);
      std::sort(by.begin(), by.end(), [&](std::size_t a, std::size_t b) {
        return effects_[a][q].mu_star > effects_[b][q].mu_star;
      });
      for (std::size_t i = 0; i < k_; ++i) rank_[by[i]][q] = static_cast<int>(i) + 1;
    }
    order_.resize(k_);
    std::iota(order_.begin(), order_.end(), 0);
    std::sort(order_.begin(), order_.end(),
              [&](std::size_t a, std::size_t b) { return rank_[a][0] < rank_[b][0]; });
  }

  // The figures' spread over every point, across the plausible ranges (min, 5 %, median,
  // 95 %, max), and whether each holds; with --optimum, the paper's verdict on each term.
  void spread_across_ranges() {
    for (std::size_t q = 0; q < responses_; ++q) {
      std::vector<double> v;
      for (const Figures& f : y_) v.push_back(f[q]);
      std::sort(v.begin(), v.end());
      const auto at = [&](double p) {
        return v[static_cast<std::size_t>(std::lround(p * static_cast<double>(v.size() - 1)))];
      };
      spread_.push_back({v.front(), at(0.05), at(0.5), at(0.95), v.back()});
      holds_.push_back(spread_[q][3] - spread_[q][1] <= holds_within(q));
    }
    if (!o_.optimum) return;
    const auto& paper = paper_significant_terms();
    for (const std::string t : kQuadraticTerms) {
      const bool in_paper = std::find(paper.begin(), paper.end(), t) != paper.end();
      (verdict_holds(t, in_paper) ? terms_hold_ : terms_fail_).push_back(t);
    }
  }

  // How often a term of uprightness's quadratic is significant across the points: a term the
  // paper lists holds when it is significant at 90 % of them, one it does not when at 10 % at
  // most (the same rule as the figures'). One replicate per design point: 5 residual df.
  double share_of_points(const std::string& term) const {
    const auto it = significant_at_.find(term);
    return static_cast<double>(it == significant_at_.end() ? 0 : it->second) /
           static_cast<double>(points_.size());
  }
  bool verdict_holds(const std::string& term, bool in_paper) const {
    return in_paper ? share_of_points(term) >= 0.9 : share_of_points(term) <= 0.1;
  }

  std::string csv() const;
  nlohmann::json json() const;
  std::string html() const;

  const std::string path_;
  const SensitivityOptions& o_;
  const Scenario base_;
  const std::span<const ModelValue> values_;
  const std::size_t k_;
  const std::size_t responses_;
  std::vector<std::vector<double>> points_;  // coded, [0, 1]
  std::vector<std::size_t> moved_;           // factor moved to reach point i (k: the base)
  std::vector<int> trajectory_of_;
  RunPlan plan_;
  std::size_t per_point_ = 1;
  std::vector<Summary> all_;
  std::vector<Figures> y_;
  std::map<std::string, int> significant_at_;  // term -> points where it is significant
  std::vector<std::array<Effect, kResponseCount>> effects_;
  std::vector<std::array<int, kResponseCount>> rank_;
  std::vector<std::size_t> order_;  // by uprightness's rank
  std::vector<std::array<double, 5>> spread_;
  std::vector<bool> holds_;  // per figure
  std::vector<std::string> terms_hold_, terms_fail_;
};

std::string SensitivityStudy::csv() const {
  std::ostringstream csv;
  csv << "run,trajectory,moved";
  for (const ModelValue& v : values_) csv << ',' << v.key;
  csv << ",uprightness_pct,damage_pct,turned_in_clamp_pct,seedlings_planted,seedlings_lodged,"
         "seedlings_fell_in_carry";
  if (o_.optimum) csv << ",optimum_contact_area_mm2,optimum_disc_speed_radps,optimum_depth_mm";
  csv << '\n';
  for (std::size_t i = 0; i < points_.size(); ++i) {
    csv << i + 1 << ',' << trajectory_of_[i] + 1 << ','
        << (moved_[i] == k_ ? "base" : values_[moved_[i]].key);
    const Summary& run = all_[i * per_point_];
    const Scenario at = planned_scenario(base_, plan_.runs[i * per_point_]);
    for (const ModelValue& v : values_) csv << ',' << v.value(at.plant);
    csv << ',' << y_[i][0] << ',' << y_[i][1] << ',' << y_[i][2] << ',' << run.seedlings_planted
        << ',' << run.seedlings_lodged << ',' << run.seedlings_fell_in_carry;
    if (o_.optimum) csv << ',' << y_[i][3] << ',' << y_[i][4] << ',' << y_[i][5];
    csv << '\n';
  }
  return csv.str();
}

nlohmann::json SensitivityStudy::json() const {
  nlohmann::json j;
  j["scenario"] = base_.name;
  j["method"] = "Morris elementary effects, 4 levels, step 2/3";
  j["trajectories"] = o_.trajectories;
  j["runs"] = plan_.runs.size();
  j["points"] = points_.size();
  j["distance_m_per_run"] = o_.distance_m;
  for (std::size_t f = 0; f < k_; ++f) {
    nlohmann::json v;
    v["key"] = values_[f].key;
    v["origin"] = origin_name(values_[f].origin);
    v["range"] = {values_[f].low, values_[f].high};
    v["in_use"] = values_[f].value(base_.plant);
    for (std::size_t q = 0; q < responses_; ++q)
      v[kResponses[q].name] = {{"mu_star", effects_[f][q].mu_star},
                               {"mu", effects_[f][q].mu},
                               {"sigma", effects_[f][q].sigma},
                               {"rank", rank_[f][q]}};
    j["values"].push_back(v);
  }
  for (std::size_t q = 0; q < responses_; ++q) {
    const auto& s = spread_[q];
    j["spread"][kResponses[q].name] = {{"min", s[0]},
                                       {"p5", s[1]},
                                       {"median", s[2]},
                                       {"p95", s[3]},
                                       {"max", s[4]},
                                       {"holds_within", holds_within(q)},
                                       {"holds", static_cast<bool>(holds_[q])}};
  }
  if (o_.optimum) {
    const auto& paper = paper_significant_terms();
    for (const std::string t : kQuadraticTerms) {
      const bool in_paper = std::find(paper.begin(), paper.end(), t) != paper.end();
      j["significant_terms"][t] = {{"share_of_points", share_of_points(t)},
                                   {"in_paper", in_paper},
                                   {"paper_holds", verdict_holds(t, in_paper)}};
    }
    j["paper_terms_holding"] = terms_hold_;
    j["paper_terms_not_holding"] = terms_fail_;
  }
  j["paper"] = {{"uprightness_pct", kPaperCentreUprightness_pct},
                {"damage_pct", kPaperCentreDamage_pct},
                {"optimum_contact_area_mm2", kPaperOptimum[0]},
                {"optimum_disc_speed_radps", kPaperOptimum[1]},
                {"optimum_depth_mm", kPaperOptimum[2]}};
  return j;
}

std::string SensitivityStudy::html() const {
  std::ostringstream html;
  html << "<!doctype html><html><head>" << report::kReportHead
       << "<title>Sensitivity: " << report::html_escape(base_.name) << "</title>"
       << report::kTablePageStyle
       << "</head><body><h1>Which model "
          "values the conclusions rest on</h1><p>Morris's elementary effects: "
       << o_.trajectories << " trajectories over " << k_ << " values, " << plan_.runs.size()
       << " runs of " << o_.distance_m
       << " m at the scenario's operating point. mu* is the mean absolute change of a figure when "
          "the value crosses its whole plausible range (in points); sigma its spread "
          "(interactions or non-linearity).</p><table><tr><th>value</th><th>origin</th><th>range"
          "</th>";
  for (std::size_t q = 0; q < responses_; ++q)
    html << "<th>" << kResponses[q].name << " mu* [" << kResponses[q].unit
         << "]</th><th>sigma</th><th>rank</th>";
  html << "</tr>";
  for (std::size_t f : order_) {
    html << "<tr><td style='text-align:left'>" << values_[f].key << "</td><td>"
         << origin_name(values_[f].origin) << "</td><td>"
         << report::formatted("%.4g", values_[f].low) << " - "
         << report::formatted("%.4g", values_[f].high) << "</td>";
    for (std::size_t q = 0; q < responses_; ++q)
      html << "<td>" << report::formatted("%.3g", effects_[f][q].mu_star) << "</td><td>"
           << report::formatted("%.3g", effects_[f][q].sigma) << "</td><td>" << rank_[f][q]
           << "</td>";
    html << "</tr>";
  }
  html << "</table><h2>The figures across the plausible ranges</h2><ul>";
  for (std::size_t q = 0; q < responses_; ++q) {
    const auto& s = spread_[q];
    html << "<li>" << kResponses[q].name << ": " << report::formatted("%.4g", s[1]) << " - "
         << report::formatted("%.4g", s[3]) << " " << kResponses[q].unit
         << " (5-95 % of the points; median " << report::formatted("%.4g", s[2]) << ")</li>";
  }
  html << "</ul><p>The paper: " << report::formatted("%.1f", kPaperCentreUprightness_pct)
       << " % upright and " << report::formatted("%.0f", kPaperCentreDamage_pct)
       << " % damaged at its optimum of "
       << optimum_text(kPaperOptimum[0], kPaperOptimum[1], kPaperOptimum[2])
       << ", a comparison and not a target.</p><h2>The model's values</h2>"
       << model_values_html(base_.plant) << "</body></html>";
  return html.str();
}

void SensitivityStudy::print(const std::string& out_dir) const {
  std::printf("%zu points, %zu runs of %.0f m: Morris, %d trajectories over %zu values\n",
              points_.size(), plan_.runs.size(), o_.distance_m, o_.trajectories, k_);
  std::printf("%-40s %-10s %8s %5s %8s %5s %8s %5s\n", "value (by uprightness mu*)", "origin",
              "upright", "rank", "damage", "rank", "turned", "rank");
  for (std::size_t f : order_)
    std::printf("%-40s %-10s %8.2f %5d %8.2f %5d %8.2f %5d\n", values_[f].key,
                origin_name(values_[f].origin), effects_[f][0].mu_star, rank_[f][0],
                effects_[f][1].mu_star, rank_[f][1], effects_[f][2].mu_star, rank_[f][2]);
  std::printf("wrote %s/{sensitivity.csv,sensitivity.json,report.html}\n", out_dir.c_str());
  for (std::size_t q = 0; q < responses_; ++q)
    std::printf("%-22s %s across the ranges: %.4g-%.4g %s (holds if within %.3g)\n",
                kResponses[q].name, holds_[q] ? "holds  " : "DOES NOT HOLD", spread_[q][1],
                spread_[q][3], kResponses[q].unit, holds_within(q));
  if (o_.optimum) {
    std::printf("terms of uprightness significant (paper's:");
    for (const std::string& t : paper_significant_terms()) std::printf(" %s", t.c_str());
    std::printf("), share of points:");
    for (const std::string t : kQuadraticTerms)
      std::printf(" %s %.0f%%", t.c_str(), 100.0 * share_of_points(t));
    std::printf("; the paper's verdict holds for %zu of %zu terms\n", terms_hold_.size(),
                std::size(kQuadraticTerms));
    const auto &area = spread_[3], &speed = spread_[4], &depth = spread_[5];
    std::printf(
        "optimum across the plausible ranges (5-95 %% of points): %.0f-%.0f mm^2, %.3f-%.3f rad/s, "
        "%.0f-%.0f mm; paper: %s\n",
        area[1], area[3], speed[1], speed[3], depth[1], depth[3],
        optimum_text(kPaperOptimum[0], kPaperOptimum[1], kPaperOptimum[2]).c_str());
  }
  std::printf(
      "across the plausible ranges (5-95 %% of runs): uprightness %.1f-%.1f %%, damage %.2f-%.2f "
      "%%; paper: %.1f %% and %.0f %%\n",
      spread_[0][1], spread_[0][3], spread_[1][1], spread_[1][3], kPaperCentreUprightness_pct,
      kPaperCentreDamage_pct);
}

}  // namespace

int run_sensitivity(const std::string& scenario_path, const std::string& out_dir,
                    const SensitivityOptions& o) {
  SensitivityStudy study(scenario_path, o);
  if (const std::string why = executor_refusal(o.executor); !why.empty())
    throw std::runtime_error(why);
  config::OutputSet out(out_dir, "planter-sim sensitivity", o.force);
  study.run(out_dir);
  study.write(out);
  study.print(out_dir);
  return 0;
}

}  // namespace planter::sim
