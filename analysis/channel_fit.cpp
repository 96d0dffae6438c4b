#include "analysis/channel_fit.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "analysis/parameter_covariance.h"
#include "analysis/residual_stats.h"

namespace planter::analysis {
namespace {

// Where each free parameter lives: the nominal vector or an effect's values.
using Layout = ParameterLayout;

Layout layout(std::vector<double>& nominal, std::vector<Effect>& effects,
              const std::vector<ParamSpec>& nominal_specs, bool include_grid) {
  Layout l;
  for (std::size_t k = 0; k < nominal.size(); ++k) {
    l.slots.push_back(&nominal[k]);
    l.specs.push_back(nominal_specs[k]);
  }
  for (auto& e : effects) {
    for (std::size_t k = 0; k < e.values.size(); ++k) {
      if (e.spec->params[k].grid && !include_grid) continue;
      l.slots.push_back(&e.values[k]);
      l.specs.push_back(e.spec->params[k]);
    }
  }
  return l;
}

// The calibration rows the fit sees: at most about 4000, none from a left-out fold.
std::vector<std::size_t> rows(const Split& split) {
  const std::size_t end = split.calibration_end;
  const std::size_t stride = std::max<std::size_t>(1, end / 4000);
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < end; k += stride)
    if (k < split.fold_from || k >= split.fold_to) out.push_back(k);
  return out;
}

// pred - y over pred's rows, through the filter if any (a non-finite error is kept as 1e6 so
// that a filter does not spread it).
std::vector<double> error_of(const std::vector<double>& pred, const std::vector<double>& y,
                             const ResidualFilter* filter) {
  std::vector<double> e(pred.size());
  for (std::size_t k = 0; k < e.size(); ++k) {
    const double v = pred[k] - y[k];
    e[k] = std::isfinite(v) ? v : 1e6;
  }
  if (filter != nullptr) (*filter)(e);
  return e;
}

struct SimulationError {
  const ChannelModel* channel;
  const Recording* rec;
  const std::vector<double>* y;
  const std::vector<std::size_t>* at;
  mutable std::vector<double> nominal;
  mutable std::vector<Effect> effects;
  Layout* lay;  // points into nominal/effects above
  const ResidualFilter* filter = nullptr;
  // The last point asked for and its residuals. Ceres asks for one point three times over an
  // iteration whose projected line search takes the whole step: the search's first trial, the
  // candidate (the same point) and the base of the next Jacobian.
  mutable std::vector<double> last_point, last_residual;
  bool operator()(double const* const* p, double* residual) const {
    const std::size_t n = lay->slots.size();
    if (last_point.size() == n && std::equal(last_point.begin(), last_point.end(), p[0])) {
      std::copy(last_residual.begin(), last_residual.end(), residual);
      return true;
    }
    for (std::size_t k = 0; k < n; ++k) *lay->slots[k] = p[0][k];
    std::vector<double> pred;
    channel->simulate(*rec, nominal, effects, pred);
    const std::vector<double> e = error_of(pred, *y, filter);
    for (std::size_t i = 0; i < at->size(); ++i) {
      const double v = e[(*at)[i]];
      residual[i] = std::isfinite(v) ? v : 1e6;
    }
    last_point.assign(p[0], p[0] + n);
    last_residual.assign(residual, residual + at->size());
    return true;
  }
};

// One Ceres solve of x within the specs' bounds, from where it is.
void run_ceres(SimulationError& functor, const std::vector<ParamSpec>& specs, std::size_t residuals,
               double huber, std::vector<double>& x) {
  // Forward differences: p + 1 simulations a Jacobian where central ones take 2p + 1. The
  // Jacobian only steers the trust region (the SDs take their own, parameter_spread()); on the
  // field log and the two slowest proof recordings the summaries were unchanged, at 0.6-0.75
  // of the CPU. It moved hil-commissioning's undetermined draft relaxation to another point of
  // its flat valley, where an unscaled J'J had read its SD as 0 (parameter_covariance.cpp).
  auto* cost = new ceres::DynamicNumericDiffCostFunction<SimulationError, ceres::FORWARD>(
      &functor, ceres::DO_NOT_TAKE_OWNERSHIP);
  cost->AddParameterBlock(static_cast<int>(x.size()));
  cost->SetNumResiduals(static_cast<int>(residuals));
  ceres::Problem problem;
  problem.AddResidualBlock(cost, huber > 0 ? new ceres::HuberLoss(huber) : nullptr, x.data());
  for (std::size_t k = 0; k < x.size(); ++k) {
    x[k] = std::clamp(x[k], specs[k].lower, specs[k].upper);
    problem.SetParameterLowerBound(x.data(), static_cast<int>(k), specs[k].lower);
    problem.SetParameterUpperBound(x.data(), static_cast<int>(k), specs[k].upper);
  }
  ceres::Solver::Options opt;
  opt.max_num_iterations = 40;
  opt.linear_solver_type = ceres::DENSE_QR;
  opt.logging_type = ceres::SILENT;
  // With bounds, Ceres can search along each trust-region step (a projected Armijo line
  // search). On these objectives it mostly backtracks: 55,268 cost evaluations for 12,725
  // Jacobians on the 10-minute hysteresis recording, many searches running to their 20 trials
  // where the forward-difference gradient promises a decrease a non-smooth path never gives.
  // The trust region alone (the step projected onto the bounds, the radius shrunk when a step
  // fails) did the same solves with 16,557 and 11,147. Alone, it left a nominal law whose
  // valley runs into a bound short of the valley's floor: solve_free_of_bounds() goes on.
  opt.max_num_line_search_step_size_iterations = 0;
  ceres::Solver::Summary summary;
  ceres::Solve(opt, &problem, &summary);
}

// Ceres keeps a problem within its bounds by projecting each trust-region step onto them: a
// parameter that ends on a bound still takes its share of every step, and the rest of the
// step, clipped of it, no longer lowers the cost. Where parameters trade along a valley that
// runs into a bound, the solve stops short of its floor (a clamp held at one force moved the
// roller over 0.5 mm: n ran to 0.9, and k_c and x0 stopped at a held-out 1.41 N with the
// search, 3.35 N without it, where 0.99 N, the noise, was there to take). So the parameters
// left on a bound are held there and the others solved again: an active-set step (Nocedal and
// Wright, "Numerical Optimization", 2nd ed., 2006, ch. 16).
void solve_free_of_bounds(SimulationError& functor, Layout& lay, std::size_t residuals,
                          double huber, std::vector<double>& x) {
  Layout free;
  std::vector<std::size_t> index;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const ParamSpec& p = lay.specs[k];
    const double tolerance = 1e-9 * std::max(1.0, std::abs(p.upper - p.lower));
    if (x[k] <= p.lower + tolerance || x[k] >= p.upper - tolerance) continue;
    free.slots.push_back(lay.slots[k]);
    free.specs.push_back(p);
    index.push_back(k);
  }
  if (index.empty() || index.size() == x.size()) return;
  for (std::size_t k = 0; k < x.size(); ++k) *lay.slots[k] = x[k];
  std::vector<double> part(index.size());
  for (std::size_t i = 0; i < index.size(); ++i) part[i] = x[index[i]];
  functor.lay = &free;
  functor.last_point.clear();
  run_ceres(functor, free.specs, residuals, huber, part);
  functor.lay = &lay;
  for (std::size_t i = 0; i < index.size(); ++i) x[index[i]] = part[i];
}

// A solved channel: its free parameters' slots in the caller's vectors, and its prediction and
// error over every row.
struct Solved {
  const ChannelModel& ch;
  const Recording& r;
  const ResidualFilter* filter;
  std::vector<double>& nominal;
  std::vector<Effect>& effects;
  Layout slots;
  std::vector<double> pred, error;
};

// Each free parameter's effect on the calibration rows' errors and on the held-out rows'
// prediction, by forward differences from the solution.
struct Sensitivities {
  Eigen::MatrixXd calibration, held;
};
Sensitivities sensitivities(Solved& s, const std::vector<std::size_t>& at,
                            std::size_t calibration_end) {
  const std::vector<double>& y = s.r.at(s.ch.output());
  const std::size_t p = s.slots.slots.size();
  const std::size_t held = y.size() - std::min(y.size(), calibration_end);
  Sensitivities out{Eigen::MatrixXd(at.size(), p),
                    Eigen::MatrixXd(static_cast<Eigen::Index>(held), static_cast<Eigen::Index>(p))};
  for (std::size_t c = 0; c < p; ++c) {
    double& slot = *s.slots.slots[c];
    const double keep = slot;
    const double h = std::max(1e-7, 1e-4 * std::abs(keep));
    slot = keep + h;
    std::vector<double> p2;
    s.ch.simulate(s.r, s.nominal, s.effects, p2);
    slot = keep;
    const std::vector<double> e2 = error_of(p2, y, s.filter);
    const auto col = static_cast<Eigen::Index>(c);
    for (std::size_t i = 0; i < at.size(); ++i)
      out.calibration(static_cast<Eigen::Index>(i), col) = (e2[at[i]] - s.error[at[i]]) / h;
    for (std::size_t i = 0; i < held; ++i) {
      const std::size_t k = calibration_end + i;
      out.held(static_cast<Eigen::Index>(i), col) = (p2[k] - s.pred[k]) / h;
    }
  }
  return out;
}

// What a ChannelFit keeps of the parameters' covariance: which nominal parameters the rows
// move, their covariance, and the first-order (delta-method) SD of the held-out prediction with
// the parameter that contributes most to it (its variance alone, correlations left out).
void record_spread(const Eigen::MatrixXd& cov, const Sensitivities& j, std::size_t nominal_count,
                   ChannelFit& spread) {
  const auto p = static_cast<std::size_t>(cov.cols());
  const std::size_t m = std::min(nominal_count, p);
  spread.nominal_exercised.assign(nominal_count, true);
  for (std::size_t c = 0; c < m; ++c)
    spread.nominal_exercised[c] = j.calibration.col(static_cast<Eigen::Index>(c)).norm() > 0.0;
  spread.nominal_covariance.assign(m * m, 0.0);
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = 0; b < m; ++b)
      spread.nominal_covariance[a * m + b] =
          cov(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
  const Eigen::Index held = j.held.rows();
  if (held == 0) return;
  const Eigen::MatrixXd jc = j.held * cov;
  const double variance =
      std::max(0.0, (jc.cwiseProduct(j.held)).sum() / static_cast<double>(held));
  spread.held_out_prediction_sd = std::sqrt(variance);
  double top_share = -1.0;
  for (Eigen::Index c = 0; c < j.held.cols(); ++c) {
    const double share = j.held.col(c).squaredNorm() * cov(c, c);
    if (share > top_share) top_share = share, spread.least_determined = static_cast<int>(c);
  }
}

// Standard deviations from the Jacobian at the solution, allowing for residuals correlated
// from row to row (parameter_covariance.h).
void parameter_spread(Solved& s, const std::vector<std::size_t>& at, std::size_t calibration_end,
                      std::vector<double>& sd, ChannelFit* spread) {
  const std::size_t p = s.slots.slots.size();
  sd.assign(p, 0.0);
  if (p == 0 || at.size() <= p) return;
  const Sensitivities j = sensitivities(s, at, calibration_end);
  Eigen::VectorXd e(static_cast<Eigen::Index>(at.size()));
  for (std::size_t i = 0; i < at.size(); ++i) e(static_cast<Eigen::Index>(i)) = s.error[at[i]];
  const Eigen::MatrixXd cov = hac_covariance(j.calibration, e).covariance;
  for (std::size_t c = 0; c < p; ++c)
    sd[c] =
        std::sqrt(std::max(0.0, cov(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(c))));
  if (spread != nullptr) record_spread(cov, j, s.nominal.size(), *spread);
}

// Solves the smooth parameters with the grid ones fixed; returns the calibration RSS.
double solve(const ChannelModel& ch, const Recording& r, const Split& split,
             std::vector<double>& nominal, std::vector<Effect>& effects, double huber,
             std::vector<double>* sd, ChannelFit* spread = nullptr,
             const ResidualFilter* filter = nullptr) {
  const std::vector<double>& y = r.at(ch.output());
  const std::vector<std::size_t> at = rows(split);
  // A row's simulation reads no further than rows_ahead() rows on: the solver's thousands of
  // simulations stop there after the last calibration row, not at the recording's end (the
  // held-out rows are 30 % of a recording).
  Recording calibration_rows;
  const Recording* simulated = &r;
  if (const std::size_t needed = at.empty() ? r.size() : at.back() + 1 + ch.rows_ahead();
      needed < r.size()) {
    calibration_rows = first_rows(r, needed);
    simulated = &calibration_rows;
  }
  SimulationError functor{&ch, simulated, &y, &at, nominal, effects, nullptr, filter, {}, {}};
  Layout lay = layout(functor.nominal, functor.effects, ch.nominal_params(), false);
  functor.lay = &lay;
  bounds_for_output(lay.specs, y);
  std::vector<double> x(lay.slots.size());
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = *lay.slots[k];
  if (!x.empty()) run_ceres(functor, lay.specs, at.size(), huber, x);
  // The nominal law's own fit goes on from its bounds: it is the base every candidate is
  // judged against, and a base left short credits an effect with the law's misfit. Not in an
  // effect's fit: tried there, a play and a hysteresis took the field log's stems' spread (the
  // force loop moves the roller with each stem) and passed every rule beside the process.
  if (!x.empty() && effects.empty()) solve_free_of_bounds(functor, lay, at.size(), huber, x);
  // Write the solution back to the caller's vectors.
  Solved s{ch, r, filter, nominal, effects, layout(nominal, effects, ch.nominal_params(), false),
           {}, {}};
  for (std::size_t k = 0; k < x.size(); ++k) *s.slots.slots[k] = x[k];
  ch.simulate(r, nominal, effects, s.pred);
  s.error = error_of(s.pred, y, filter);
  double rss = 0;
  for (std::size_t i : at) rss += s.error[i] * s.error[i];
  if (sd) parameter_spread(s, at, split.calibration_end, *sd, spread);
  return rss;
}

double robust_scale(const std::vector<double>& pred, const std::vector<double>& y,
                    std::size_t end) {
  std::vector<double> a;
  for (std::size_t k = 0; k < end; k += std::max<std::size_t>(1, end / 4000))
    a.push_back(std::abs(pred[k] - y[k]));
  if (a.empty()) return 1.0;
  std::nth_element(a.begin(), a.begin() + static_cast<long>(a.size() / 2), a.end());
  return std::max(1e-9, 1.4826 * a[a.size() / 2]);
}

// Standard deviations back to their owners (a grid parameter: its resolution, not a fit), the
// prediction, its errors and the parameter count.
void finish(const ChannelModel& ch, const Recording& r, const Split& split,
            const std::vector<double>& sd, double resolution, ChannelFit& fit) {
  std::size_t k = 0;
  fit.nominal_sd.assign(fit.nominal.size(), 0.0);
  for (auto& v : fit.nominal_sd) v = sd.size() > k ? sd[k++] : 0.0;
  fit.effect_sd.clear();
  for (const auto& e : fit.effects) {
    std::vector<double> s;
    for (const auto& p : e.spec->params)
      s.push_back(p.grid ? resolution : (sd.size() > k ? sd[k++] : 0.0));
    fit.effect_sd.push_back(s);
  }
  predict(ch, r, split, fit);
  fit.parameters = static_cast<int>(fit.nominal.size());
  for (const auto& e : fit.effects) fit.parameters += static_cast<int>(e.values.size());
}

}  // namespace

std::size_t fitted_rows(const Split& split) { return rows(split).size(); }

void predict(const ChannelModel& ch, const Recording& r, const Split& split, ChannelFit& fit) {
  const std::vector<double>& y = r.at(ch.output());
  ch.simulate(r, fit.nominal, fit.effects, fit.prediction);
  fit.rms_calibration = rms_between(fit.prediction, y, 0, split.calibration_end);
  fit.rms_held_out = rms_between(fit.prediction, y, split.calibration_end, y.size());
}

double rms_on_fitted_rows(const std::vector<double>& pred, const std::vector<double>& y,
                          const Split& split) {
  double sum = 0.0;
  const std::vector<std::size_t> at = rows(split);
  for (std::size_t k : at) sum += (pred[k] - y[k]) * (pred[k] - y[k]);
  return at.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(at.size()));
}

ParameterLayout fitted_layout(const ChannelModel& ch, ChannelFit& f) {
  return layout(f.nominal, f.effects, ch.nominal_params(), false);
}

std::vector<FittedValue> fitted_values(const ChannelModel& ch, const ChannelFit& f) {
  std::vector<FittedValue> out;
  const auto specs = ch.nominal_params();
  for (std::size_t k = 0; k < specs.size(); ++k)
    out.push_back({specs[k].name, specs[k].unit, f.nominal[k],
                   k < f.nominal_sd.size() ? f.nominal_sd[k] : 0.0});
  for (std::size_t e = 0; e < f.effects.size(); ++e)
    for (std::size_t k = 0; k < f.effects[e].values.size(); ++k) {
      const ParamSpec& p = f.effects[e].spec->params[k];
      if (!p.grid)
        out.push_back({p.name, p.unit, f.effects[e].values[k],
                       e < f.effect_sd.size() ? f.effect_sd[e][k] : 0.0});
    }
  return out;
}

ChannelFit refit(const ChannelModel& ch, const Recording& r, const Split& split,
                 const ChannelFit& fit, double* rss) {
  ChannelFit out;
  out.nominal = fit.nominal;
  out.effects = fit.effects;
  const double huber = 3.0 * robust_scale(fit.prediction, r.at(ch.output()), split.calibration_end);
  std::vector<double> sd;
  const double sum = solve(ch, r, split, out.nominal, out.effects, huber, &sd, &out);
  if (rss) *rss = sum;
  // A grid parameter keeps the resolution the original fit reached.
  double resolution = 0.0;
  for (std::size_t e = 0; e < fit.effects.size() && e < fit.effect_sd.size(); ++e)
    for (std::size_t k = 0; k < fit.effects[e].values.size(); ++k)
      if (fit.effects[e].spec->params[k].grid) resolution = fit.effect_sd[e][k];
  finish(ch, r, split, sd, resolution, out);
  out.bic = fit.bic;
  return out;
}

double signal_span(const std::vector<double>& v) {
  if (v.empty()) return 0.0;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

Effect initial_effect(const EffectSpec& spec, const Recording& r,
                      const std::vector<double>& residual) {
  Effect e{&spec, {}};
  if (spec.start != nullptr) {
    e.values = spec.start(r, residual);
  } else {
    for (const auto& p : spec.params) e.values.push_back(p.initial);
  }
  return e;
}

void bounds_for_output(std::vector<ParamSpec>& specs, const std::vector<double>& y) {
  double size = 0.0;
  for (double v : y) size = std::max(size, std::abs(v));
  size = std::max(size, 1e-9);
  for (ParamSpec& spec : specs) {
    if (!spec.of_output_size) continue;
    spec.lower *= size;
    spec.upper *= size;
    spec.of_output_size = false;
  }
}

bool at_range_edge(const ParamSpec& p, double v) {
  const double tolerance = 1e-6 * (p.upper - p.lower);
  if (!(p.upper > p.lower)) return false;  // unbounded (a grid's top comes from the data)
  const bool at_lower = !p.grid && v <= p.lower + tolerance && p.lower != 0.0;
  return at_lower || v >= p.upper - tolerance;
}

void widen_delay_by_row(ChannelFit& fit, const Recording& rows_read) {
  const std::size_t n = rows_read.size();
  if (n < 2) return;
  const double row_s = (rows_read.t[n - 1] - rows_read.t[0]) / static_cast<double>(n - 1);
  for (std::size_t e = 0; e < fit.effects.size() && e < fit.effect_sd.size(); ++e)
    if (fit.effects[e].spec->kind == EffectKind::kDelay && !fit.effect_sd[e].empty())
      fit.effect_sd[e][0] = std::max(fit.effect_sd[e][0], row_s);
}

namespace {

// A parameter that is searched on a grid (non-smooth): which effect's which value, and the
// values searched.
struct GridParam {
  std::size_t effect, index;
  std::vector<double> values;
};

// The grid values for the non-smooth parameters, scaled to the data.
std::vector<GridParam> grid_of(const ChannelModel& ch, const Recording& r,
                               const std::vector<Effect>& effects, bool hold_located) {
  const std::vector<double>& y = r.at(ch.output());
  const double in_span = r.has(ch.input()) ? signal_span(r.at(ch.input())) : 1.0;
  const double out_span = signal_span(y);
  std::vector<GridParam> grid;
  bool fresh_grid = hold_located;  // a grid parameter not yet located, or held by the caller
  for (const Effect& fx : effects)
    for (std::size_t k = 0; k < fx.values.size(); ++k)
      fresh_grid = fresh_grid || (fx.spec->params[k].grid && !(fx.values[k] > 0.0));
  for (std::size_t e = 0; e < effects.size(); ++e) {
    for (std::size_t k = 0; k < effects[e].values.size(); ++k) {
      const ParamSpec& p = effects[e].spec->params[k];
      if (!p.grid) continue;
      const double hi = effects[e].spec->grid_upper != nullptr
                            ? effects[e].spec->grid_upper(in_span, out_span, y)
                            : p.upper;
      GridParam g{e, k, {}};
      if (effects[e].values[k] > 0.0 && fresh_grid) {
        // Already located, beside one searched afresh (a second effect's) or where the caller
        // holds it: held where it was, so the search is the fresh one's 16 values, not 16 times
        // five (a play beside a delay took 5.4 s of a 10-minute clamp's 25).
        g.values.push_back(effects[e].values[k]);
      } else if (effects[e].values[k] > 0.0) {
        // Already located (a pair refit): refine around it.
        for (double f : {0.8, 0.9, 1.0, 1.1, 1.2}) g.values.push_back(effects[e].values[k] * f);
      } else {
        for (int s = 1; s <= 16; ++s) g.values.push_back(hi * s / 16.0);
      }
      grid.push_back(g);
    }
  }
  return grid;
}

// The search over the grid parameters' values: each value tried has the smooth parameters
// solved from the nominal's start beside it, and the best (lowest calibration RSS) is kept.
class GridSearch {
 public:
  GridSearch(const ChannelModel& ch, const Recording& r, const Split& split,
             const std::vector<double>& nominal_start, const std::vector<Effect>& effects,
             double huber, const ResidualFilter* filter)
      : ch_(ch),
        r_(r),
        split_(split),
        nominal_start_(nominal_start),
        effects_(effects),
        huber_(huber),
        filter_(filter),
        best_nominal_(nominal_start),
        best_effects_(effects) {}

  // Effects fx (their grid values set) tried; returns the calibration RSS.
  double try_effects(std::vector<Effect> fx) {
    std::vector<double> nom = nominal_start_;
    const double rss = solve(ch_, r_, split_, nom, fx, huber_, nullptr, nullptr, filter_);
    if (rss < best_rss_) {
      best_rss_ = rss;
      best_nominal_ = std::move(nom);
      best_effects_ = std::move(fx);
    }
    return rss;
  }

  // Every combination of the grids' values (at most two grid parameters in practice).
  void every_combination(const std::vector<GridParam>& grid) {
    std::vector<std::size_t> idx(grid.size(), 0);
    while (true) {
      std::vector<Effect> fx = effects_;
      for (std::size_t g = 0; g < grid.size(); ++g)
        fx[grid[g].effect].values[grid[g].index] = grid[g].values[idx[g]];
      try_effects(std::move(fx));
      std::size_t g = 0;
      while (g < grid.size() && ++idx[g] == grid[g].values.size()) idx[g++] = 0;
      if (g == grid.size()) break;
    }
  }

  // A single grid parameter best at its grid's top goes on upwards, a grid step at a time (at
  // most 32 more), to its own bound: the top is where the data's spans guessed the physics
  // would end, not where it must. A speed loop's friction held the disc 0.154 rad/s short of a
  // command spanning 0.498 (31 %), beyond a band's grid of 30 %; left at the top, the fit's
  // other parameters bent around it and a second effect took the credit for moving it on.
  void extend_past_top(GridParam& g) {
    const ParamSpec& p = effects_[g.effect].spec->params[g.index];
    const double step = g.values[1] - g.values[0];
    const double limit = p.upper > p.lower ? p.upper : std::numeric_limits<double>::infinity();
    for (int more = 0; more < 32 && step > 0.0; ++more) {
      const double top = g.values.back();
      if (best_effects_[g.effect].values[g.index] != top || top + step > limit) break;
      std::vector<Effect> fx = effects_;
      fx[g.effect].values[g.index] = top + step;
      g.values.push_back(top + step);
      try_effects(std::move(fx));
    }
  }

  // A single grid parameter is refined below its grid: the step is halved three times around
  // the best value (a delay of 80 ms on a 31 ms grid), then placed between its last neighbours
  // by the parabola through their calibration RSS (successive parabolic interpolation, Brent,
  // "Algorithms for Minimization without Derivatives", 1973, ch. 5). The parabola only moves
  // the value: a dead zone's width left on its grid leaves a constant on the moving rows that
  // a gain error would otherwise take up. Returns the +-, the last step: the fit cannot place
  // it closer than the grid it searched (a narrower interval, tried, held the truth less often).
  double refine_below_grid(const GridParam& g) {
    const ParamSpec& p = effects_[g.effect].spec->params[g.index];
    const double top = *std::max_element(g.values.begin(), g.values.end());
    auto value_of = [&](const std::vector<Effect>& fx) { return fx[g.effect].values[g.index]; };
    // A value already solved is not solved again (the last halving's neighbours).
    std::vector<std::pair<double, double>> solved;
    auto try_value = [&](double v) {
      for (const auto& [at, rss] : solved) {
        if (at == v) return rss;
      }
      std::vector<Effect> fx = best_effects_;
      fx[g.effect].values[g.index] = v;
      const double rss = try_effects(std::move(fx));
      solved.emplace_back(v, rss);
      return rss;
    };
    double step = std::abs(g.values[1] - g.values[0]);
    for (int round = 0; round < 3; ++round) {
      step *= 0.5;
      const double centre = value_of(best_effects_);
      for (double v : {centre - step, centre + step}) {
        if (v > p.lower && v <= top) try_value(v);
      }
    }
    const double centre = value_of(best_effects_);
    const double lo = centre - step;
    const double hi = centre + step;
    if (lo > p.lower && hi <= top) {
      const double rss_c = best_rss_;
      const double rss_lo = try_value(lo);
      const double rss_hi = try_value(hi);
      const double curvature = rss_lo - 2.0 * rss_c + rss_hi;
      // Only a minimum inside the bracket (centre the lowest of the three) is interpolated.
      if (curvature > 0.0 && rss_c <= rss_lo && rss_c <= rss_hi) {
        const double v = centre + 0.5 * step * (rss_lo - rss_hi) / curvature;
        if (std::abs(v - centre) > 1e-6 * step) try_value(v);
      }
    }
    return step;
  }

  const std::vector<double>& best_nominal() const { return best_nominal_; }
  const std::vector<Effect>& best_effects() const { return best_effects_; }

 private:
  const ChannelModel& ch_;
  const Recording& r_;
  const Split& split_;
  const std::vector<double>& nominal_start_;
  const std::vector<Effect>& effects_;
  double huber_;
  const ResidualFilter* filter_;
  double best_rss_ = std::numeric_limits<double>::infinity();
  std::vector<double> best_nominal_;
  std::vector<Effect> best_effects_;
};

}  // namespace

ChannelFit fit_channel(const ChannelModel& ch, const Recording& r, const Split& split,
                       const std::vector<double>& nominal_start, std::vector<Effect> effects,
                       const ResidualFilter* filter, bool hold_located) {
  const std::vector<double>& y = r.at(ch.output());
  std::vector<GridParam> grid = grid_of(ch, r, effects, hold_located);
  // A first solve without the effects' help sets the Huber scale from the nominal residual.
  std::vector<double> pred;
  ch.simulate(r, nominal_start, {}, pred);
  const std::vector<double> zero(y.size(), 0.0);
  const double huber = 3.0 * robust_scale(error_of(pred, y, filter), zero, split.calibration_end);

  GridSearch search(ch, r, split, nominal_start, effects, huber, filter);
  search.every_combination(grid);
  double resolution = 0.0;
  if (grid.size() == 1 && grid[0].values.size() > 1) {
    search.extend_past_top(grid[0]);
    resolution = search.refine_below_grid(grid[0]);
  }
  ChannelFit fit;
  fit.nominal = search.best_nominal();
  fit.effects = search.best_effects();
  std::vector<double> sd;
  const double rss = solve(ch, r, split, fit.nominal, fit.effects, huber, &sd, &fit, filter);
  finish(ch, r, split, sd, resolution, fit);
  const double n = static_cast<double>(rows(split).size());
  fit.bic = n * std::log(std::max(rss, 1e-300) / n) + fit.parameters * std::log(n);
  return fit;
}

double fold_rms(const ChannelModel& ch, const Recording& r, const Split& split,
                const ChannelFit& fit) {
  const std::vector<double>& y = r.at(ch.output());
  std::vector<double> nominal = fit.nominal;
  std::vector<Effect> effects = fit.effects;
  const double huber = 3.0 * robust_scale(fit.prediction, y, split.calibration_end);
  solve(ch, r, split, nominal, effects, huber, nullptr);
  std::vector<double> pred;
  ch.simulate(r, nominal, effects, pred);
  return rms_between(pred, y, split.fold_from, split.fold_to);
}

}  // namespace planter::analysis
