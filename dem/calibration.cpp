#include "dem/calibration.h"

#include <algorithm>
#include <array>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "config/output_set.h"
#include "dem/calibration_runs.h"
#include "dem/dem_keys.h"
#include "plan/executor.h"
#include "plan/folder_lock.h"

namespace planter::dem {
namespace {

using doe::box_behnken_3;
using doe::fit_main_effects;
using doe::fit_quadratic_3;
using doe::plackett_burman_12;
using doe::predict_quadratic_3;
using doe::solve_quadratic_3_for;

constexpr double kAscentStep = 0.2;  // coded units per step for the steepest factor
constexpr int kAscentSteps = 8;

// Runs every run of `runs` not already kept in DIR/runs: a stage's plan, on the executor.
class RunPool {
 public:
  RunPool(const CalibrationOptions& o, CalibrationReport& r,
          const std::function<void(const std::string&)>& progress)
      : opt_(o), report_(r), progress_(progress), dir_(o.out_dir + "/runs") {
    config::make_directories(dir_);
  }

  // False when the new-run budget stopped it before every run was done.
  bool run(std::vector<DesignRun>& runs, const char* stage) {
    std::vector<std::size_t> todo;
    for (std::size_t k = 0; k < runs.size(); ++k) {
      if (auto kept = kept_result(dir_, runs[k].setup)) {
        runs[k].result = *kept;
        runs[k].reused = true;
        ++report_.reused_runs;
      } else {
        todo.push_back(k);
      }
    }
    bool complete = true;
    if (opt_.max_new_runs >= 0) {
      const auto left = static_cast<std::size_t>(std::max(0, opt_.max_new_runs - report_.new_runs));
      if (todo.size() > left) {
        todo.resize(left);
        complete = false;
      }
    }
    if (todo.empty()) return complete;
    std::vector<std::string> keys;
    for (std::size_t k : todo) keys.push_back(place_run(dir_, runs[k].setup));
    std::string slug = stage;
    std::replace(slug.begin(), slug.end(), ' ', '-');
    const std::string plan_dir = opt_.out_dir + "/plans/" + slug;
    const std::string plan_path = plan_dir + "/plan.json";
    write_stage_plan(plan_path, dir_, keys);
    std::mutex mu;
    plan::PlanRuns plan;
    plan.dir = plan_dir;
    plan.count = todo.size();
    plan.complete = [&](std::size_t i) {
      return kept_result(dir_, runs[todo[i]].setup).has_value();
    };
    plan.run_here = [&](std::size_t i) {
      const CompressionResult r = run_kept(dir_, keys[i]);
      const std::lock_guard lock(mu);
      char line[160];
      std::snprintf(line, sizeof line, "%s run %zu/%zu: peak %.1f N at %.2f mm", stage, todo[i] + 1,
                    runs.size(), r.peak_force_N, r.peak_displacement_m * 1e3);
      progress_(line);
    };
    if (opt_.executor.kind == "slurm")  // the program's own path, only where a task needs it
      plan.task_command = plan::shell_quoted(plan::task_program(opt_.executor)) + " plan-run " +
                          plan::shell_quoted(std::filesystem::absolute(plan_path).string());
    plan.by_hand = "planter-dem plan-run " + plan_path + " INDEX, for each INDEX from 0 to " +
                   std::to_string(todo.size() - 1);
    plan.what = "planter-dem calibration";
    plan::ExecutorOptions ex = opt_.executor;
    ex.jobs = opt_.jobs;
    // Here, each run says its peak as it ends (above); through Slurm, the executor's progress
    // line says the runs done, running and failed.
    plan::execute(plan, ex, ex.kind == "slurm" ? std::string("calibration: ") + stage : "");
    // Every run is kept now (execute throws otherwise): the results, as they were written.
    for (std::size_t k : todo) {
      const auto kept = kept_result(dir_, runs[k].setup);
      if (!kept) throw std::runtime_error(dir_ + "/" + run_key(runs[k].setup) + ".json: missing");
      runs[k].result = *kept;
      ++report_.new_runs;
    }
    return complete;
  }

 private:
  const CalibrationOptions& opt_;
  CalibrationReport& report_;
  const std::function<void(const std::string&)>& progress_;
  std::string dir_;
};

DesignRun make_run(const CalibrationOptions& o, const std::vector<Factor>& factors,
                   const std::vector<double>& coded) {
  DesignRun d;
  d.coded = coded;
  d.setup = o.base;
  for (std::size_t k = 0; k < factors.size(); ++k)
    factors[k].apply(d.setup, factors[k].value(coded[k]));
  return d;
}

// The bond value outside the --params file's allowed range, named, or "".
std::string outside_allowed_range(const BondParameters& b) {
  const std::pair<const config::ConfigKey*, double> values[] = {
      {&config::key_in(kDemBodyKeys, "bond.normal_stiffness_N_m3"), b.normal_stiffness_N_m3},
      {&config::key_in(kDemBodyKeys, "bond.shear_stiffness_N_m3"), b.shear_stiffness_N_m3},
      {&config::key_in(kDemBodyKeys, "bond.tensile_strength_Pa"), b.tensile_strength_Pa},
      {&config::key_in(kDemBodyKeys, "bond.shear_strength_Pa"), b.shear_strength_Pa}};
  for (const auto& [key, v] : values) {
    if (v < key->min || v > key->max) {
      char text[200];
      std::snprintf(text, sizeof text, "bond.%s = %.4g, outside its allowed %g .. %g %s",
                    std::string(key->name).c_str(), v, key->min, key->max,
                    std::string(key->unit).c_str());
      return text;
    }
  }
  return "";
}

Eigen::VectorXd responses(const std::vector<DesignRun>& runs) {
  Eigen::VectorXd y(static_cast<Eigen::Index>(runs.size()));
  for (std::size_t k = 0; k < runs.size(); ++k)
    y(static_cast<Eigen::Index>(k)) = runs[k].result.peak_force_N;
  return y;
}

}  // namespace

double Factor::value(double coded) const {
  if (log_scale) {
    const double lo = std::log10(low), hi = std::log10(high);
    return std::pow(10.0, 0.5 * (lo + hi) + 0.5 * coded * (hi - lo));
  }
  return 0.5 * (low + high) + 0.5 * coded * (high - low);
}

std::vector<Factor> screening_factors() {
  // Levels: the paper's Table 3 is not in its text; the intermediate levels it names for
  // X4-X8 (0.35, 0.15, 0.5, 0.45, 0.25) are the midpoints here. Stiffness and strength span
  // the published plant-stem range and include the paper's calibrated values.
  return {
      {"X1 bond stiffness S_n=S_t", "N/m^3", 1e7, 5e9, true,
       [](CompressionSetup& s, double v) {
         s.bonds.normal_stiffness_N_m3 = v;
         s.bonds.shear_stiffness_N_m3 = v;
       }},
      {"X2 bond strength sigma_c=tau_c", "Pa", 1e4, 5.643e7, true,
       [](CompressionSetup& s, double v) {
         s.bonds.tensile_strength_Pa = v;
         s.bonds.shear_strength_Pa = v;
       }},
      {"X3 Poisson's ratio", "-", 0.25, 0.45, false,
       [](CompressionSetup& s, double v) { s.seedling_material.poisson = v; }},
      {"X4 seedling restitution", "-", 0.2, 0.5, false,
       [](CompressionSetup& s, double v) { s.seedling_material.restitution = v; }},
      {"X5 seedling rolling friction", "-", 0.05, 0.25, false,
       [](CompressionSetup& s, double v) { s.seedling_material.rolling_friction = v; }},
      {"X6 seedling static friction", "-", 0.3, 0.7, false,
       [](CompressionSetup& s, double v) { s.seedling_material.friction = v; }},
      {"X7 seedling-steel restitution", "-", 0.3, 0.6, false,
       [](CompressionSetup& s, double v) { s.platen_material.restitution = v; }},
      {"X8 seedling-steel static friction", "-", 0.1, 0.4, false,
       [](CompressionSetup& s, double v) { s.platen_material.friction = v; }},
  };
}

namespace {

using Coded = std::vector<double>;  // a point in the screening factors' coded units

// 1. Plackett-Burman screening, and its main effects.
bool screen(const CalibrationOptions& o, CalibrationReport& r, RunPool& pool,
            const std::vector<std::string>& names) {
  const int nf = static_cast<int>(r.factors.size());
  const Eigen::MatrixXd pb = plackett_burman_12(nf);
  for (Eigen::Index row = 0; row < pb.rows(); ++row) {
    Coded c(static_cast<std::size_t>(nf));
    for (int k = 0; k < nf; ++k) c[static_cast<std::size_t>(k)] = pb(row, k);
    r.screening.push_back(make_run(o, r.factors, c));
  }
  if (!pool.run(r.screening, "screening")) return false;
  r.screening_anova = fit_main_effects(pb, responses(r.screening), names);
  return true;
}

// The significant factors, strongest first; Box-Behnken needs three.
void choose_three(const CalibrationOptions& o, CalibrationReport& r) {
  const int nf = static_cast<int>(r.factors.size());
  std::vector<int> order(static_cast<std::size_t>(nf));
  for (int k = 0; k < nf; ++k) order[static_cast<std::size_t>(k)] = k;
  const auto& terms = r.screening_anova.terms;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return std::abs(terms[static_cast<std::size_t>(a)].coefficient) >
           std::abs(terms[static_cast<std::size_t>(b)].coefficient);
  });
  int significant = 0;
  for (int k : order) {
    if (terms[static_cast<std::size_t>(k)].p_value < o.significance) ++significant;
  }
  r.chosen.assign(order.begin(), order.begin() + 3);
  std::sort(r.chosen.begin(), r.chosen.end());
  r.chosen_reason = std::to_string(significant) + " factor(s) significant at p < " +
                    std::to_string(o.significance).substr(0, 4) +
                    (significant >= 3 ? "; the three strongest go on"
                                      : "; the three largest effects go on, the rest from "
                                        "the next largest");
}

// 2. The direction of steepest ascent (or descent) from the centre towards the target, the
// steepest chosen factor at 1.
Coded ascent_direction(const CalibrationOptions& o, const CalibrationReport& r) {
  const auto& terms = r.screening_anova.terms;
  const double towards = r.screening_anova.intercept > o.target_N ? -1.0 : 1.0;
  double b_max = 0.0;
  for (int k : r.chosen)
    b_max = std::max(b_max, std::abs(terms[static_cast<std::size_t>(k)].coefficient));
  Coded direction(r.factors.size(), 0.0);
  for (int k : r.chosen) {
    direction[static_cast<std::size_t>(k)] =
        b_max > 0 ? towards * terms[static_cast<std::size_t>(k)].coefficient / b_max : 0.0;
  }
  return direction;
}

Coded path_point(const Coded& direction, double step) {
  Coded c(direction.size(), 0.0);
  for (std::size_t k = 0; k < direction.size(); ++k) c[k] = step * kAscentStep * direction[k];
  return c;
}

// The steps along the path, and the one nearest the target.
bool ascend(const CalibrationOptions& o, CalibrationReport& r, RunPool& pool,
            const Coded& direction) {
  for (int s = 0; s < kAscentSteps; ++s)
    r.ascent.push_back(make_run(o, r.factors, path_point(direction, s)));
  if (!pool.run(r.ascent, "steepest ascent")) return false;
  double best_err = 1e300;
  for (int s = 0; s < kAscentSteps; ++s) {
    const double err =
        std::abs(r.ascent[static_cast<std::size_t>(s)].result.peak_force_N - o.target_N);
    if (err < best_err) {
      best_err = err;
      r.best_step = s;
    }
  }
  return true;
}

// 3. Box-Behnken around the best step. The paper put the neighbouring steps at -1 and +1;
// here the response turns sharply where bonds start to fail (a collapse), so the levels are
// half a step away, where a quadratic can follow it. A factor the path hardly moves gets a
// quarter of its screening range instead.
struct BoxBehnkenFrame {
  Coded centre;                // the best step, in screening units
  std::array<double, 3> half;  // each chosen factor's +-1, in screening units
  std::array<std::size_t, 3> chosen;
  Coded to_screening(const Eigen::Vector3d& x) const {
    Coded c = centre;
    for (std::size_t m = 0; m < 3; ++m) c[chosen[m]] += x(static_cast<Eigen::Index>(m)) * half[m];
    return c;
  }
};

BoxBehnkenFrame frame_around_best(CalibrationReport& r, const Coded& direction) {
  BoxBehnkenFrame frame{path_point(direction, r.best_step), {}, {}};
  for (std::size_t m = 0; m < 3; ++m) {
    const auto k = static_cast<std::size_t>(r.chosen[m]);
    const double h = std::abs(kAscentStep * direction[k]);
    frame.chosen[m] = k;
    frame.half[m] = h >= 0.1 ? 0.5 * h : 0.25;
    const Factor& f = r.factors[k];
    r.bb_low.push_back(f.value(frame.centre[k] - frame.half[m]));
    r.bb_centre.push_back(f.value(frame.centre[k]));
    r.bb_high.push_back(f.value(frame.centre[k] + frame.half[m]));
  }
  return frame;
}

bool box_behnken(const CalibrationOptions& o, CalibrationReport& r, RunPool& pool,
                 const std::vector<std::string>& names, const BoxBehnkenFrame& frame) {
  // One centre point: the simulation is deterministic, replicates would be identical.
  const Eigen::MatrixXd bb = box_behnken_3(1);
  for (Eigen::Index row = 0; row < bb.rows(); ++row) {
    r.box_behnken.push_back(make_run(o, r.factors, frame.to_screening(bb.row(row).transpose())));
  }
  if (!pool.run(r.box_behnken, "box-behnken")) return false;
  std::vector<std::string> bb_names;
  for (int k : r.chosen) bb_names.push_back(names[static_cast<std::size_t>(k)]);
  r.surface = fit_quadratic_3(bb, responses(r.box_behnken), bb_names);
  return true;
}

// How far a run misses the targets: <= 1 is within 2 % of the force and 3 % of the displacement.
double miss(const CalibrationOptions& o, const CompressionResult& res) {
  const double f = std::abs(res.peak_force_N / o.target_N - 1.0);
  const double d = o.target_displacement_mm > 0
                       ? std::abs(res.peak_displacement_m * 1e3 / o.target_displacement_mm - 1.0)
                       : 0.0;
  return std::max(f / 0.02, d / 0.03);
}

// One refinement step from a run: S and sigma_c scaled together move the force, their ratio
// the peak's displacement.
DesignRun refinement_step(const CalibrationOptions& o, const DesignRun& from) {
  DesignRun next = from;
  next.reused = false;
  BondParameters& b = next.setup.bonds;
  double ratio_scale = 1.0;
  if (o.target_displacement_mm > 0) {
    const double dp = from.result.peak_displacement_m * 1e3;
    ratio_scale = from.result.first_peak_found
                      ? std::clamp(o.target_displacement_mm / dp, 0.33, 3.0)
                      : 0.7;  // no collapse yet: weaker bonds
  }
  double force_scale = from.result.peak_force_N > 0
                           ? std::clamp(o.target_N / from.result.peak_force_N, 0.25, 4.0)
                           : 1.0;
  // Damped steps (0.7 of the full one in log terms): near the collapse the peak jumps.
  force_scale = std::pow(force_scale, 0.7);
  ratio_scale = std::pow(ratio_scale, 0.7);
  b.normal_stiffness_N_m3 *= force_scale;
  b.shear_stiffness_N_m3 *= force_scale;
  b.tensile_strength_Pa *= force_scale * ratio_scale;
  b.shear_strength_Pa *= force_scale * ratio_scale;
  return next;
}

// 5. Refinement (beyond the paper; the Box-Behnken optimum can miss when the response turns
// sharply at the collapse): steps until within the targets, each from the last run, the best
// kept.
bool refine(const CalibrationOptions& o, CalibrationReport& r, RunPool& pool) {
  DesignRun latest = r.verification;
  for (int it = 0; it < o.refinement_runs && miss(o, r.calibrated.result) > 1.0; ++it) {
    DesignRun next = refinement_step(o, latest);
    // A step out of a parameter file's allowed range could neither run from its file nor be
    // the calibrated file: the refinement stops there and says so.
    if (const std::string why = outside_allowed_range(next.setup.bonds); !why.empty()) {
      r.refinement_stopped = "the next step would set " + why;
      break;
    }
    std::vector<DesignRun> one{next};
    if (!pool.run(one, "refinement")) return false;
    r.refinement.push_back(one.front());
    latest = one.front();
    if (miss(o, latest.result) < miss(o, r.calibrated.result)) r.calibrated = latest;
  }
  return true;
}

}  // namespace

CalibrationReport calibrate(const CalibrationOptions& o,
                            const std::function<void(const std::string&)>& progress) {
  const plan::FolderLock lock(
      o.out_dir, "another planter-dem calibration is writing this folder now (give --out another)");
  CalibrationReport r;
  r.factors = screening_factors();
  RunPool pool(o, r, progress);
  std::vector<std::string> names;
  for (const auto& f : r.factors) names.push_back(f.name.substr(0, 2));
  if (!screen(o, r, pool, names)) return r;
  choose_three(o, r);
  const Coded direction = ascent_direction(o, r);
  if (!ascend(o, r, pool, direction)) return r;
  const BoxBehnkenFrame frame = frame_around_best(r, direction);
  if (!box_behnken(o, r, pool, names, frame)) return r;

  // 4. The optimum of the surface, and a run there to check it.
  r.optimum_coded = solve_quadratic_3_for(r.surface, o.target_N);
  r.predicted_N = predict_quadratic_3(r.surface, r.optimum_coded);
  std::vector<DesignRun> verify{make_run(o, r.factors, frame.to_screening(r.optimum_coded))};
  if (!pool.run(verify, "verification")) return r;
  r.verification = verify.front();
  r.calibrated = r.verification;
  if (!refine(o, r, pool)) return r;
  r.complete = true;
  return r;
}

}  // namespace planter::dem
