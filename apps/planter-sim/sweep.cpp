#include "apps/planter-sim/sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>
#include <vector>

#include "apps/version/version.h"
#include "config/output_set.h"
#include "doe/doe.h"
#include "doe/doe_report.h"
#include "report/html_text.h"
#include "sim/plant/model_values.h"
#include "sim/runner/model_assumptions.h"
#include "sim/runner/run_plan.h"
#include "sim/runner/scenario.h"

namespace planter::sim {
namespace {

// The paper's factors (Table 4): centre and half-range of each, coded -1, 0, +1.
struct Factor {
  const char* name;
  const char* unit;
  double centre, half_range;
  [[nodiscard]] double value(double coded) const { return centre + half_range * coded; }
  [[nodiscard]] double coded(double value) const { return (value - centre) / half_range; }
};
constexpr Factor kFactors[3] = {{"contact area", "mm^2", 255.0, 150.0},
                                {"disc speed", "rad/s", 0.25, 0.10},
                                {"depth", "mm", 100.0, 60.0}};
const std::vector<std::string> kTermNames{"A", "B", "C"};

// The paper's findings for uprightness (its Tables 5-6 and optimisation): the significant
// terms, the optimum and the centre point.
const std::vector<std::string> kPaperSignificant{"A", "B", "C", "BC", "A^2", "B^2", "C^2"};
constexpr int kCentrePoints = 3;

struct Run {
  int point = 0, replicate = 0;
  double uprightness_pct = 0, damage_pct = 0, peak_force_N = 0, clamp_force_max_N = 0;
  int planted = 0, damaged = 0;
};

// The standard error of a point's damage rate in points, pooled over its replicates, with
// the Agresti-Coull adjustment so that no damaged seedling does not read as exact.
double damage_standard_error_pts(const std::vector<Run>& runs, int point) {
  double n = 0, k = 0;
  for (const Run& r : runs) {
    if (r.point != point) continue;
    n += r.planted;
    k += r.damaged;
  }
  const double p = (k + 2.0) / (n + 4.0);
  return 100.0 * std::sqrt(p * (1.0 - p) / (n + 4.0));
}

// The operating point at one coded point of the design.
OperatingPoint operating_point_at(const Scenario& base, const Eigen::RowVector3d& coded) {
  const double omega = kFactors[1].value(coded(1));
  return {omega * base.board.controller.sigma.disc_radius_m / base.plant.route.speed_mps,
          kFactors[2].value(coded(2)), kFactors[0].value(coded(0))};
}

// Desirability as Design-Expert sets it by default: each goal over the observed range of its
// response; uprightness up, the peak radial force on the seedling down.
doe::Optimum optimum_of(const doe::Anova& upright_fit, const Eigen::VectorXd& upright,
                        const doe::Anova& force_fit, const Eigen::VectorXd& force) {
  return doe::desirability_optimum_3({{&upright_fit, upright.minCoeff(), upright.maxCoeff()},
                                      {&force_fit, force.maxCoeff(), force.minCoeff()}});
}

// Runs the (point, replicate) pairs `todo` as one plan (stage `stage` of the sweep) on the
// executor; each run its own process, seed and output set.
std::vector<Run> run_all(const Scenario& base, const std::string& scenario_path,
                         const Eigen::MatrixXd& design,
                         const std::vector<std::pair<int, int>>& todo, const SweepOptions& o,
                         const std::string& runs, int stage) {
  RunPlan plan = new_plan(scenario_path, apps::version());
  for (const auto& [point, replicate] : todo) {
    const Eigen::RowVector3d coded = design.row(point);
    PlannedRun r;
    r.distance_m = o.distance_m;
    r.seed = base.seed + 1000u * static_cast<std::uint64_t>(replicate) +
             static_cast<std::uint64_t>(point);
    r.operating_point = operating_point_at(base, coded);
    plan.runs.push_back(r);
  }
  const std::vector<Summary> results =
      execute_plan(runs + "/stage-" + std::to_string(stage), plan,
                   executor_for(o.executor, o.jobs, o.force), "sweep");
  std::vector<Run> out;
  for (std::size_t i = 0; i < todo.size(); ++i) {
    const Summary& r = results[i];
    out.push_back({todo[i].first, todo[i].second, r.uprightness_pct, r.damage_pct,
                   r.seedling_peak_force_mean_N, r.clamp_force_max_N, r.seedlings_planted,
                   r.seedlings_damaged});
  }
  return out;
}

nlohmann::json anova_json(const doe::Anova& a, const doe::LackOfFit& l) {
  nlohmann::json j = doe::anova_json(a);
  if (l.available) j["lack_of_fit"] = doe::lack_of_fit_json(l);
  return j;
}

std::string anova_html(const std::string& title, const std::string& unit, const doe::Anova& a,
                       const doe::LackOfFit& l) {
  std::ostringstream h;
  h << "<h3>" << title << " [" << unit << "]</h3>" << doe::anova_table_html(a) << "<p>Lack of fit ";
  if (l.available)
    h << "F " << report::formatted("%.3g", l.f_value) << " on " << l.df << " and "
      << l.pure_error_df << " df, p " << report::formatted("%.3g", l.p_value)
      << (l.p_value < 0.05 ? " (significant)" : "");
  else
    h << "not testable (no replicates)";
  h << ". Bold: p &lt; 0.05.</p>";
  return h.str();
}

// Dark blue (low, u = 0) to yellow (high, u = 1).
std::string colour(double u) {
  char b[32];
  std::snprintf(b, sizeof b, "rgb(%d,%d,%d)", static_cast<int>(30 + 220 * u),
                static_cast<int>(40 + 180 * u), static_cast<int>(120 - 90 * u));
  return b;
}

// A filled map of a surface over two factors, the third held at `fixed`, with the paper's
// optimum (cross) and this sweep's (circle) marked.
std::string surface_map(const std::string& title, const std::string& unit, const doe::Anova& a,
                        int fx, int fy, const Eigen::Vector3d& fixed, const Eigen::Vector3d& paper,
                        const Eigen::Vector3d& found, double physical_min, double physical_max) {
  constexpr int kCells = 40;
  // Drawn for a phone's 376 px of width, where its text is 13 px as drawn; the notes go below.
  constexpr double kSize = 220, kLeft = 58, kTop = 50;
  std::vector<double> z;
  for (int j = 0; j < kCells; ++j) {
    for (int i = 0; i < kCells; ++i) {
      Eigen::Vector3d x = fixed;
      x(fx) = -1.0 + 2.0 * (i + 0.5) / kCells;
      x(fy) = 1.0 - 2.0 * (j + 0.5) / kCells;
      // The quadratic extrapolates past what the quantity can be (uprightness above 100 %):
      // shown clipped to its physical range, and said under the map.
      z.push_back(std::clamp(doe::predict_quadratic_3(a, x), physical_min, physical_max));
    }
  }
  const double lo = *std::min_element(z.begin(), z.end());
  const double hi = *std::max_element(z.begin(), z.end());
  std::ostringstream s;
  const double width = 376, height = kTop + kSize + 104;
  // viewBox: the map scales whole to the screen instead of being cut.
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height
    << "' viewBox='0 0 " << width << ' ' << height << "' font-family='sans-serif' font-size='13'>"
    << "<text x='4' y='16'>" << report::html_escape(title) << " [" << unit << "]</text>"
    << "<text x='4' y='34'>" << kFactors[3 - fx - fy].name << " at "
    << report::formatted("%.4g", kFactors[3 - fx - fy].value(fixed(3 - fx - fy))) << " "
    << kFactors[3 - fx - fy].unit << "</text>";
  const double cell = kSize / kCells;
  for (int j = 0; j < kCells; ++j) {
    for (int i = 0; i < kCells; ++i) {
      const double u = hi > lo ? (z[static_cast<std::size_t>(j * kCells + i)] - lo) / (hi - lo) : 0;
      s << "<rect x='" << kLeft + i * cell << "' y='" << kTop + j * cell << "' width='"
        << cell + 0.5 << "' height='" << cell + 0.5 << "' fill='" << colour(u) << "'/>";
    }
  }
  auto px = [&](double c) { return kLeft + (c + 1.0) / 2.0 * kSize; };
  auto py = [&](double c) { return kTop + (1.0 - c) / 2.0 * kSize; };
  const double below = kTop + kSize;
  for (double c : {-1.0, 0.0, 1.0}) {
    // The ends' labels stay inside the map's width; the middle one is centred.
    const char* anchor = c < 0 ? "start" : c > 0 ? "end" : "middle";
    s << "<text x='" << px(c) << "' y='" << below + 16 << "' text-anchor='" << anchor << "'>"
      << report::formatted("%.4g", kFactors[fx].value(c)) << "</text><text x='" << kLeft - 4
      << "' y='" << std::clamp(py(c) + 5, kTop + 10, below) << "' text-anchor='end'>"
      << report::formatted("%.4g", kFactors[fy].value(c)) << "</text>";
  }
  s << "<text x='" << px(0.0) << "' y='" << below + 34 << "' text-anchor='middle'>"
    << kFactors[fx].name << " [" << kFactors[fx].unit << "]</text>"
    << "<text x='14' y='" << kTop + kSize / 2 << "' text-anchor='middle' transform='rotate(-90 14 "
    << kTop + kSize / 2 << ")'>" << kFactors[fy].name << " [" << kFactors[fy].unit << "]</text>";
  s << "<path d='M" << px(paper(fx)) - 7 << ',' << py(paper(fy)) - 7 << " l14,14 m0,-14 l-14,14' "
    << "stroke='white' stroke-width='2.5'/><circle cx='" << px(found(fx)) << "' cy='"
    << py(found(fy)) << "' r='6' fill='none' stroke='red' stroke-width='2.5'/>";
  // The colour scale: a bar from low to high with five labelled steps.
  const double lx = kLeft + kSize + 8;
  for (int k = 0; k < 20; ++k) {
    s << "<rect x='" << lx << "' y='" << kTop + kSize - (k + 1) * kSize / 20 << "' width='12' "
      << "height='" << kSize / 20 + 0.5 << "' fill='" << colour((k + 0.5) / 20.0) << "'/>";
  }
  for (int k = 0; k <= 4; ++k) {
    s << "<text x='" << lx + 15 << "' y='" << kTop + kSize - k * kSize / 4 + 5 << "'>"
      << report::formatted("%.4g", lo + (hi - lo) * k / 4.0) << " " << unit << "</text>";
  }
  s << "<text x='4' y='" << below + 56 << "'>x paper's optimum (projected)</text>"
    << "<text x='230' y='" << below + 56 << "' fill='red'>o this sweep's</text>"
    << "<text x='4' y='" << below + 76 << "'>the quadratic, clipped to "
    << (std::isfinite(physical_max) ? report::formatted("%.4g", physical_min) + "-" +
                                          report::formatted("%.4g", physical_max)
                                    : "at least " + report::formatted("%.4g", physical_min))
    << " " << unit << "</text><text x='4' y='" << below + 94
    << "'>where it extrapolates past what can be</text></svg>";
  return s.str();
}

}  // namespace

ExecutorOptions executor_for(const ExecutorOptions& o, int jobs, bool force) {
  ExecutorOptions e = o;
  e.jobs = jobs;
  e.replace_other_plan = force;
  e.made_by = apps::version();
  return e;
}

std::vector<PlannedRun> design_runs(const Scenario& base, const PlannedRun& at) {
  const Eigen::MatrixXd design = doe::box_behnken_3(kCentrePoints);
  std::vector<PlannedRun> out;
  for (Eigen::Index p = 0; p < design.rows(); ++p) {
    PlannedRun r = at;
    r.seed = at.seed + static_cast<std::uint64_t>(p);
    r.operating_point = operating_point_at(base, design.row(p));
    out.push_back(r);
  }
  return out;
}

DesignOptimum design_optimum(const std::vector<Summary>& results) {
  const Eigen::MatrixXd design = doe::box_behnken_3(kCentrePoints);
  const Eigen::Index n = design.rows();
  Eigen::VectorXd upright(n), force(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    upright(i) = results[static_cast<std::size_t>(i)].uprightness_pct;
    force(i) = results[static_cast<std::size_t>(i)].seedling_peak_force_mean_N;
  }
  const doe::Anova upright_fit = doe::fit_quadratic_3(design, upright, kTermNames);
  const doe::Optimum best =
      optimum_of(upright_fit, upright, doe::fit_quadratic_3(design, force, kTermNames), force);
  DesignOptimum o{kFactors[0].value(best.coded(0)),
                  kFactors[1].value(best.coded(1)),
                  kFactors[2].value(best.coded(2)),
                  best.desirability,
                  {}};
  for (const auto& t : upright_fit.terms)
    if (t.p_value < 0.05) o.significant_terms.push_back(t.name);
  return o;
}

const std::vector<std::string>& paper_significant_terms() { return kPaperSignificant; }

std::string optimum_text(double area_mm2, double disc_speed_radps, double depth_mm) {
  return report::formatted("%.0f", area_mm2) + " mm^2, " +
         report::formatted("%.3f", disc_speed_radps) + " rad/s, " +
         report::formatted("%.0f", depth_mm) + " mm";
}

double design_span(int factor) { return 2.0 * kFactors[factor].half_range; }

std::string runs_folder(const std::string& out_dir) {
  std::string d = out_dir;
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  return d + ".runs";
}

namespace {

// What the sweep found: its runs and the surfaces, optimum and centre point fitted to them.
struct SweepFindings {
  Eigen::MatrixXd design;
  int points = 0;
  std::vector<Run> runs;
  doe::Anova a_up, a_dmg, a_force;
  doe::LackOfFit l_up, l_dmg, l_force;
  doe::Optimum best;
  Eigen::Vector3d paper;
  double opt[3] = {0, 0, 0};
  double centre_up = 0, centre_dmg = 0, worst_se = 0;
  std::vector<std::string> differ;  // uprightness terms whose significance differs from the paper's
  std::string differ_text;
  std::vector<Summary> force_curve;
  double machine_setpoint_N = 0;
};

constexpr std::size_t kConstantRows = std::size(kClampForceCurve_N);
double force_row_N(const SweepFindings& f, std::size_t i) {
  return i < kConstantRows ? kClampForceCurve_N[i] : f.machine_setpoint_N;
}
const char* grip_name(std::size_t i) { return i < kConstantRows ? "constant" : "per stem"; }

// Every point with the first replicates; then one more where damage is not yet resolved.
std::vector<Run> run_replicates(const Scenario& base, const std::string& scenario_path,
                                const Eigen::MatrixXd& design, const SweepOptions& o,
                                const std::string& runs_dir) {
  const int points = static_cast<int>(design.rows());
  int stage = 0;
  std::vector<Run> runs;
  std::vector<int> replicates(static_cast<std::size_t>(points), 0);
  std::vector<std::pair<int, int>> todo;
  for (int rep = 0; rep < o.replicates; ++rep)
    for (int p = 0; p < points; ++p) todo.emplace_back(p, rep);
  while (!todo.empty()) {
    for (const Run& r : run_all(base, scenario_path, design, todo, o, runs_dir, ++stage))
      runs.push_back(r);
    for (const auto& [p, rep] : todo) replicates[static_cast<std::size_t>(p)] = rep + 1;
    todo.clear();
    for (int p = 0; p < points; ++p) {
      const int n = replicates[static_cast<std::size_t>(p)];
      if (n < o.max_replicates && damage_standard_error_pts(runs, p) > o.damage_precision_pts)
        todo.emplace_back(p, n);
    }
  }
  std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) {
    return a.point != b.point ? a.point < b.point : a.replicate < b.replicate;
  });
  return runs;
}

// The surfaces (one observation per run), the optimum, the centre point's means and the worst
// damage precision reached.
void fit_surfaces(SweepFindings& f) {
  const auto n = static_cast<Eigen::Index>(f.runs.size());
  Eigen::MatrixXd coded(n, 3);
  Eigen::VectorXd upright(n), damage(n), force(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Run& r = f.runs[static_cast<std::size_t>(i)];
    coded.row(i) = f.design.row(r.point);
    upright(i) = r.uprightness_pct;
    damage(i) = r.damage_pct;
    force(i) = r.peak_force_N;
  }
  f.a_up = doe::fit_quadratic_3(coded, upright, kTermNames);
  f.a_dmg = doe::fit_quadratic_3(coded, damage, kTermNames);
  f.a_force = doe::fit_quadratic_3(coded, force, kTermNames);
  f.l_up = doe::lack_of_fit(coded, upright, f.a_up);
  f.l_dmg = doe::lack_of_fit(coded, damage, f.a_dmg);
  f.l_force = doe::lack_of_fit(coded, force, f.a_force);
  f.best = optimum_of(f.a_up, upright, f.a_force, force);
  f.paper =
      Eigen::Vector3d(kFactors[0].coded(kPaperOptimum[0]), kFactors[1].coded(kPaperOptimum[1]),
                      kFactors[2].coded(kPaperOptimum[2]));
  for (int k = 0; k < 3; ++k) f.opt[k] = kFactors[k].value(f.best.coded(k));
  int centre_n = 0;
  for (const Run& r : f.runs) {
    if (f.design.row(r.point).norm() == 0.0) {
      f.centre_up += r.uprightness_pct;
      f.centre_dmg += r.damage_pct;
      ++centre_n;
    }
  }
  f.centre_up /= std::max(1, centre_n);
  f.centre_dmg /= std::max(1, centre_n);
  for (int p = 0; p < f.points; ++p)
    f.worst_se = std::max(f.worst_se, damage_standard_error_pts(f.runs, p));
  for (const auto& t : f.a_up.terms) {
    const bool ours = t.p_value < 0.05;
    const bool theirs = std::find(kPaperSignificant.begin(), kPaperSignificant.end(), t.name) !=
                        kPaperSignificant.end();
    if (ours != theirs)
      f.differ.push_back(t.name + (ours ? " (significant here, not in the paper)"
                                        : " (significant in the paper, not here)"));
  }
  for (const auto& d : f.differ) f.differ_text += (f.differ_text.empty() ? "" : ", ") + d;
  if (f.differ_text.empty()) f.differ_text = "none";
}

// The grip's trade-off at the design's centre: the clamp force set-point from 40 to 120 N
// (issue 27: both sides, slipping and crushing, before anyone optimises the force). Each a
// constant force, then the clamp that grips each stem under its own ceiling (issue 50) at the
// machine's set-point: the last row.
std::vector<Summary> run_force_curve(const Scenario& base, const std::string& scenario_path,
                                     const SweepOptions& o, const std::string& runs_dir) {
  RunPlan force_plan = new_plan(scenario_path, apps::version());
  for (double f : kClampForceCurve_N) {
    PlannedRun r;
    r.seed = base.seed;
    r.distance_m = o.distance_m;
    r.operating_point = operating_point_at(base, Eigen::RowVector3d::Zero());
    r.clamp_setpoint_N = f;
    r.per_stem_grip = false;
    force_plan.runs.push_back(r);
  }
  PlannedRun per_stem = force_plan.runs.back();
  per_stem.clamp_setpoint_N.reset();
  per_stem.per_stem_grip = true;
  force_plan.runs.push_back(per_stem);
  return execute_plan(runs_dir + "/force-curve", force_plan,
                      executor_for(o.executor, o.jobs, o.force), "sweep: clamp force");
}

// The interior maximum of uprightness along factor `k`, through the optimum: where the
// surface's slope along it is zero, if it curves down.
std::string interior_max(const SweepFindings& f, int k) {
  const auto& t = f.a_up.beta;
  // d/dx_k of the quadratic at the optimum's other coordinates: linear + interactions + 2 q x.
  const int lin = 1 + k, sq = 7 + k;
  const int inter[3][3] = {{-1, 4, 5}, {4, -1, 6}, {5, 6, -1}};
  double slope0 = t(lin);
  for (int g = 0; g < 3; ++g)
    if (g != k) slope0 += t(inter[k][g]) * f.best.coded(g);
  const double curvature = 2.0 * t(sq);
  if (curvature >= 0.0) return "no: the surface curves up or is flat";
  const double x = -slope0 / curvature;
  if (x <= -1.0 || x >= 1.0)
    return "no: the maximum lies outside the design, at " +
           report::formatted("%.4g", kFactors[k].value(x)) + " " + kFactors[k].unit;
  return "yes, at " + report::formatted("%.4g", kFactors[k].value(x)) + " " + kFactors[k].unit;
}

// sweep.csv: every run.
std::string sweep_csv(const SweepFindings& f) {
  std::ostringstream csv;
  csv << "point,replicate,contact_area_mm2,disc_speed_radps,depth_mm,uprightness_pct,damage_pct,"
         "seedling_peak_force_mean_N,clamp_force_max_N,seedlings_planted,seedlings_damaged\n";
  for (const Run& r : f.runs) {
    csv << r.point + 1 << ',' << r.replicate + 1 << ',' << kFactors[0].value(f.design(r.point, 0))
        << ',' << kFactors[1].value(f.design(r.point, 1)) << ','
        << kFactors[2].value(f.design(r.point, 2)) << ',' << r.uprightness_pct << ','
        << r.damage_pct << ',' << r.peak_force_N << ',' << r.clamp_force_max_N << ',' << r.planted
        << ',' << r.damaged << '\n';
  }
  return csv.str();
}

nlohmann::json sweep_json(const Scenario& base, const SweepFindings& f, const SweepOptions& o) {
  nlohmann::json j;
  j["scenario"] = base.name;
  j["runs"] = f.runs.size();
  j["distance_m_per_run"] = o.distance_m;
  j["damage_standard_error_pts_worst"] = f.worst_se;
  j["uprightness"] = anova_json(f.a_up, f.l_up);
  j["damage"] = anova_json(f.a_dmg, f.l_dmg);
  j["seedling_peak_force"] = anova_json(f.a_force, f.l_force);
  j["optimum"] = {{"contact_area_mm2", f.opt[0]},
                  {"disc_speed_radps", f.opt[1]},
                  {"depth_mm", f.opt[2]},
                  {"desirability", f.best.desirability},
                  {"uprightness_pct", doe::predict_quadratic_3(f.a_up, f.best.coded)},
                  {"seedling_peak_force_N", doe::predict_quadratic_3(f.a_force, f.best.coded)}};
  j["paper_optimum"] = {{"contact_area_mm2", kPaperOptimum[0]},
                        {"disc_speed_radps", kPaperOptimum[1]},
                        {"depth_mm", kPaperOptimum[2]}};
  j["terms_differing_from_paper"] = f.differ;
  j["centre_uprightness_pct"] = f.centre_up;
  j["centre_damage_pct"] = f.centre_dmg;
  j["paper_centre"] = {{"uprightness_pct", kPaperCentreUprightness_pct},
                       {"damage_pct", kPaperCentreDamage_pct}};
  for (std::size_t i = 0; i < f.force_curve.size(); ++i) {
    const Summary& s = f.force_curve[i];
    j["force_curve"].push_back({{"clamp_force_N", force_row_N(f, i)},
                                {"grip", grip_name(i)},
                                {"uprightness_pct", s.uprightness_pct},
                                {"damage_pct", s.damage_pct},
                                {"skips", s.truth_skips},
                                {"fell_in_carry", s.seedlings_fell_in_carry},
                                {"turned_in_clamp", s.seedlings_turned_in_clamp},
                                {"slid_in_clamp", s.seedlings_slid_in_clamp},
                                {"planted", s.seedlings_planted}});
  }
  return j;
}

std::string sweep_html(const Scenario& base, const SweepFindings& f, const SweepOptions& o) {
  std::ostringstream html;
  html << "<!doctype html><html><head>" << report::kReportHead
       << "<title>Sweep: " << report::html_escape(base.name) << "</title>"
       << report::kTablePageStyle << "</head><body>"
       << "<h1>The paper's Box-Behnken experiment, simulated</h1><p>" << f.runs.size()
       << " runs of " << o.distance_m << " m on " << f.points << " design points (" << kCentrePoints
       << " centre points), at least " << o.replicates
       << " replicates each, more where the damage rate's standard error was above "
       << o.damage_precision_pts
       << " points (worst reached: " << report::formatted("%.2f", f.worst_se)
       << ").</p><h2>Optimum (desirability: uprightness up, peak radial force down)</h2><p>"
       << optimum_text(f.opt[0], f.opt[1], f.opt[2]) << " (desirability "
       << report::formatted("%.3f", f.best.desirability)
       << "); the paper's: " << optimum_text(kPaperOptimum[0], kPaperOptimum[1], kPaperOptimum[2])
       << ". Terms of uprightness whose significance differs from the paper's: "
       << report::html_escape(f.differ_text) << ". Centre point: uprightness "
       << report::formatted("%.2f", f.centre_up) << " % (paper "
       << report::formatted("%.1f", kPaperCentreUprightness_pct) << " predicted), damage "
       << report::formatted("%.2f", f.centre_dmg) << " % (paper "
       << report::formatted("%.0f", kPaperCentreDamage_pct) << ").</p>"
       << surface_map("uprightness", "%", f.a_up, 1, 2, f.best.coded, f.paper, f.best.coded, 0.0,
                      100.0)
       << surface_map("uprightness", "%", f.a_up, 0, 1, f.best.coded, f.paper, f.best.coded, 0.0,
                      100.0)
       << surface_map("peak radial force on the seedling", "N", f.a_force, 1, 2, f.best.coded,
                      f.paper, f.best.coded, 0.0, std::numeric_limits<double>::infinity())
       << "<h2>Response surfaces (coded factors A area, B disc speed, C depth)</h2>"
       << anova_html("Uprightness", "%", f.a_up, f.l_up)
       << anova_html("Damage rate", "%", f.a_dmg, f.l_dmg)
       << anova_html("Peak radial force on the seedling", "N", f.a_force, f.l_force)
       << "<h2>Clamp force: grip against crushing, at the design's centre</h2>"
       << "<table><tr><th>set-point [N]</th><th>uprightness [%]</th><th>damage [%]</th>"
          "<th>skips</th><th>fell from the clamp</th><th>turned in the clamp</th><th>slid in "
          "the clamp</th><th>planted</th></tr>";
  for (std::size_t i = 0; i < f.force_curve.size(); ++i) {
    const Summary& s = f.force_curve[i];
    html << "<tr><td>" << force_row_N(f, i) << (i < kConstantRows ? "" : ", each stem's ceiling")
         << "</td><td>" << report::formatted("%.2f", s.uprightness_pct) << "</td><td>"
         << report::formatted("%.2f", s.damage_pct) << "</td><td>" << s.truth_skips << "</td><td>"
         << s.seedlings_fell_in_carry << "</td><td>" << s.seedlings_turned_in_clamp << "</td><td>"
         << s.seedlings_slid_in_clamp << "</td><td>" << s.seedlings_planted << "</td></tr>";
  }
  html << "</table><h2>Model values</h2><p>Every value the figures rest on, its origin and "
          "plausible range; <code>planter-sim sensitivity</code> ranks them.</p>"
       << model_values_html(base.plant) << "<h2>Model assumptions</h2><ul>";
  for (const std::string& a : model_assumptions(base))
    html << "<li>" << report::html_escape(a) << "</li>";
  html << "</ul></body></html>";
  return html.str();
}

void print_anova(const char* name, const doe::Anova& a, const doe::LackOfFit& l) {
  std::printf(
      "%s: R^2 %.4f, adjusted %.4f, model p %.3g, lack of fit %s\n  significant (p < 0.05):", name,
      a.r2, a.r2_adjusted, a.model_p,
      l.available ? report::formatted("p %.3g", l.p_value).c_str() : "not testable");
  for (const auto& t : a.terms)
    if (t.p_value < 0.05) std::printf(" %s", t.name.c_str());
  std::printf("\n");
}

// What the sweep prints: the figures, then where it wrote them, the optimum last.
void print_sweep(const SweepFindings& f, const SweepOptions& o, int jobs,
                 const std::string& out_dir) {
  std::printf(
      "%zu runs of %.0f m on %d points, %d jobs; damage resolved to +-%.2f points (worst "
      "point; goal %.2f)\n",
      f.runs.size(), o.distance_m, f.points, jobs, f.worst_se, o.damage_precision_pts);
  print_anova("uprightness", f.a_up, f.l_up);
  print_anova("damage", f.a_dmg, f.l_dmg);
  print_anova("peak radial force", f.a_force, f.l_force);
  std::printf("terms of uprightness differing from the paper: %s\n", f.differ_text.c_str());
  std::printf("interior maximum of uprightness in disc speed: %s\n", interior_max(f, 1).c_str());
  std::printf("interior maximum of uprightness in depth: %s\n", interior_max(f, 2).c_str());
  std::printf(
      "centre point: uprightness %.2f %% (paper %.1f; the tilt scatter is calibrated to it), "
      "damage %.2f %% (paper %.0f)\n",
      f.centre_up, kPaperCentreUprightness_pct, f.centre_dmg, kPaperCentreDamage_pct);
  std::printf(
      "clamp force at the centre: set-point, uprightness, damage, skips, turned in clamp\n");
  for (std::size_t i = 0; i < f.force_curve.size(); ++i)
    std::printf("  %5.0f N  %6.2f %%  %5.2f %%  %3d  %4d%s\n", force_row_N(f, i),
                f.force_curve[i].uprightness_pct, f.force_curve[i].damage_pct,
                f.force_curve[i].truth_skips, f.force_curve[i].seedlings_turned_in_clamp,
                i < kConstantRows ? "" : "  (per stem: each under its own ceiling)");
  std::printf("wrote %s/{sweep.csv,sweep.json,report.html}\n", out_dir.c_str());
  std::printf("optimum: %s (desirability %.3f); paper: %s\n",
              optimum_text(f.opt[0], f.opt[1], f.opt[2]).c_str(), f.best.desirability,
              optimum_text(kPaperOptimum[0], kPaperOptimum[1], kPaperOptimum[2]).c_str());
}

}  // namespace

int run_sweep(const std::string& scenario_path, const std::string& out_dir, const SweepOptions& o) {
  Scenario base = load_scenario(scenario_path);
  for (const auto& w : base.board.warnings)
    std::fprintf(stderr, "planter-sim: warning: %s\n", w.c_str());
  if (const std::string why = executor_refusal(o.executor); !why.empty())
    throw std::runtime_error(why);
  config::OutputSet out(out_dir, "planter-sim sweep", o.force);
  SweepFindings f;
  f.design = doe::box_behnken_3(kCentrePoints);
  f.points = static_cast<int>(f.design.rows());
  const int jobs =
      o.jobs > 0 ? o.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const std::string runs_dir = runs_folder(out_dir);
  f.runs = run_replicates(base, scenario_path, f.design, o, runs_dir);
  fit_surfaces(f);
  f.machine_setpoint_N = base.board.controller.clamp.setpoint_N;
  f.force_curve = run_force_curve(base, scenario_path, o, runs_dir);
  out.write("sweep.csv", sweep_csv(f));
  out.write("sweep.json", sweep_json(base, f, o).dump(2) + "\n");
  out.write("report.html", sweep_html(base, f, o));
  out.commit();
  print_sweep(f, o, jobs, out_dir);
  return 0;
}

}  // namespace planter::sim
