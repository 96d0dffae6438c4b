#include "analysis/disturbance.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "analysis/residual_stats.h"

namespace planter::analysis {
namespace {

// The process's shape in the fit's own coordinates: log wavelength, log damping, log q (the
// process's variance over the noise's, the gain normalised to an RMS of 1).
using Shape = std::array<double, 3>;

// exp(M) of a 2x2 matrix in closed form: with m half its trace and N = M - m I, N^2 = delta I
// (Cayley-Hamilton), so exp(N) = c I + s N with c, s the cosh or cos series of sqrt(delta).
Eigen::Matrix2d expm2(const Eigen::Matrix2d& M) {
  const double m = 0.5 * M.trace();
  const Eigen::Matrix2d N = M - m * Eigen::Matrix2d::Identity();
  const double delta = -N.determinant();
  double c = 1.0 + 0.5 * delta, s = 1.0 + delta / 6.0;
  if (delta > 1e-10) {
    const double r = std::sqrt(delta);
    c = std::cosh(r), s = std::sinh(r) / r;
  } else if (delta < -1e-10) {
    const double r = std::sqrt(-delta);
    c = std::cos(r), s = std::sin(r) / r;
  }
  return std::exp(m) * (c * Eigen::Matrix2d::Identity() + s * N);
}

// What the filter is run on: the residual, its gain normalised to an RMS of 1 where non-zero,
// and each row's step along the row.
struct Series {
  std::vector<double> e, g, ds;
  std::size_t end = 0;   // calibration rows
  std::size_t skip = 0;  // rows before the constant is known, left out of every likelihood
  double prior_b = 0.0;  // the constant's prior variance, in units of R (diffuse)
};

struct Filtered {
  double neg2ll = std::numeric_limits<double>::infinity();
  double r = 0.0;  // R concentrated out
  double mean = 0.0;
};

struct Trace {
  std::vector<double> nu, s;  // innovations, their variance in units of R
  // For the smoother (when asked): the state and covariance after each row's update, and
  // predicted to it before.
  bool keep_states = false;
  std::vector<Eigen::Vector3d> x_filtered, x_predicted;
  std::vector<Eigen::Matrix3d> p_filtered, p_predicted;
};

// The transition over each row's step for one wavelength and damping (q does not enter).
std::vector<Eigen::Matrix2d> transitions(const Series& x, double omega, double zeta) {
  Eigen::Matrix2d a;
  a << 0.0, 1.0, -omega * omega, -2.0 * zeta * omega;
  std::vector<Eigen::Matrix2d> phi(x.ds.size());
  for (std::size_t k = 0; k < x.ds.size(); ++k) phi[k] = expm2(a * x.ds[k]);
  return phi;
}

// The Kalman filter over rows [0, to) for states (d, d', constant), R = 1; the likelihood over
// rows [skip, end), unless only the trace is wanted (a logarithm a row saved). q = 0 is the
// constant and white noise alone.
Filtered run_filter(const Series& x, const std::vector<Eigen::Matrix2d>& phi, double omega,
                    double q, std::size_t to, Trace* trace, bool likelihood = true) {
  const Eigen::Matrix2d p_inf = q * Eigen::Vector2d(1.0, omega * omega).asDiagonal();
  Eigen::Matrix3d p = Eigen::Matrix3d::Zero();
  p.topLeftCorner<2, 2>() = p_inf;
  p(2, 2) = x.prior_b;
  Eigen::Vector3d state = Eigen::Vector3d::Zero();
  double sum_nu2 = 0.0, sum_log_s = 0.0;
  std::size_t n = 0;
  if (trace) trace->nu.assign(to, 0.0), trace->s.assign(to, 0.0);
  const bool keep = trace != nullptr && trace->keep_states;
  if (keep) {
    trace->x_filtered.resize(to), trace->x_predicted.resize(to);
    trace->p_filtered.resize(to), trace->p_predicted.resize(to);
  }
  for (std::size_t k = 0; k < to; ++k) {
    if (k > 0) {
      const Eigen::Matrix2d& f = phi[k];
      state.head<2>() = f * state.head<2>();
      const Eigen::Matrix2d p_dd = p.topLeftCorner<2, 2>();
      p.topLeftCorner<2, 2>() = f * p_dd * f.transpose() + (p_inf - f * p_inf * f.transpose());
      const Eigen::Vector2d cross = f * p.topRightCorner<2, 1>();
      p.topRightCorner<2, 1>() = cross;
      p.bottomLeftCorner<1, 2>() = cross.transpose();
    }
    if (keep) trace->x_predicted[k] = state, trace->p_predicted[k] = p;
    const Eigen::Vector3d h(x.g[k], 0.0, x.g[k]);
    const Eigen::Vector3d ph = p * h;
    const double s = h.dot(ph) + 1.0;
    const double nu = x.e[k] - h.dot(state);
    const Eigen::Vector3d gain = ph / s;
    state += gain * nu;
    p -= gain * ph.transpose();
    p = 0.5 * (p + p.transpose());
    if (likelihood && k >= x.skip && k < x.end)
      sum_nu2 += nu * nu / s, sum_log_s += std::log(s), ++n;
    if (trace) trace->nu[k] = nu, trace->s[k] = s;
    if (keep) trace->x_filtered[k] = state, trace->p_filtered[k] = p;
  }
  Filtered out;
  if (n == 0) return out;
  out.r = std::max(sum_nu2 / static_cast<double>(n), 1e-300);
  out.neg2ll =
      static_cast<double>(n) * (std::log(2.0 * std::numbers::pi * out.r) + 1.0) + sum_log_s;
  out.mean = state(2);
  return out;
}

Filtered evaluate(const Series& x, const Shape& z, std::size_t to = 0, Trace* trace = nullptr) {
  const double omega = 2.0 * std::numbers::pi / std::exp(z[0]);
  return run_filter(x, transitions(x, omega, std::exp(z[1])), omega, std::exp(z[2]),
                    to ? to : x.end, trace);
}

// The grid's best shape: wavelengths from four steps to half the row, dampings from a sharp
// peak to a low-pass, variances from a hundredth of the noise's to ten million times it, a
// decade apart (Nelder-Mead refines from there).
Shape grid_search(const Series& x, double lambda_lo, double lambda_hi) {
  Shape best{};
  double best_value = std::numeric_limits<double>::infinity();
  constexpr int kLambdas = 10, kQs = 10;
  for (int i = 0; i < kLambdas; ++i) {
    const double ln_lambda =
        std::log(lambda_lo) + std::log(lambda_hi / lambda_lo) * i / (kLambdas - 1);
    for (const double zeta : {0.1, 0.3, 1.0, 3.0}) {
      const double omega = 2.0 * std::numbers::pi / std::exp(ln_lambda);
      const std::vector<Eigen::Matrix2d> phi = transitions(x, omega, zeta);
      for (int j = 0; j < kQs; ++j) {
        const double ln_q = std::log(1e-2) + std::log(10.0) * j;
        const double v = run_filter(x, phi, omega, std::exp(ln_q), x.end, nullptr).neg2ll;
        if (v < best_value) best_value = v, best = {ln_lambda, std::log(zeta), ln_q};
      }
    }
  }
  return best;
}

// Nelder-Mead from the grid's best (Nelder & Mead, Comput. J. 7, 1965): the likelihood is
// smooth in the log parameters but its derivatives would need the filter's own.
Shape refine(const Series& x, Shape start, const Shape& lo, const Shape& hi) {
  auto f = [&](Shape z) {
    for (std::size_t i = 0; i < 3; ++i)
      if (z[i] < lo[i] || z[i] > hi[i]) return std::numeric_limits<double>::infinity();
    return evaluate(x, z).neg2ll;
  };
  std::array<Shape, 4> v{start, start, start, start};
  for (std::size_t i = 0; i < 3; ++i) v[i + 1][i] += 0.3;
  std::array<double, 4> fv{};
  for (std::size_t i = 0; i < 4; ++i) fv[i] = f(v[i]);
  for (int it = 0; it < 120; ++it) {
    std::array<std::size_t, 4> order{0, 1, 2, 3};
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return fv[a] < fv[b]; });
    if (fv[order[3]] - fv[order[0]] < 1e-3) break;
    Shape centre{};
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t i = 0; i < 3; ++i) centre[i] += v[order[j]][i] / 3.0;
    auto along = [&](double t) {
      Shape z;
      for (std::size_t i = 0; i < 3; ++i) z[i] = centre[i] + t * (v[order[3]][i] - centre[i]);
      return z;
    };
    const Shape reflected = along(-1.0);
    const double fr = f(reflected);
    if (fr < fv[order[0]]) {
      const Shape expanded = along(-2.0);
      const double fe = f(expanded);
      v[order[3]] = fe < fr ? expanded : reflected, fv[order[3]] = std::min(fe, fr);
    } else if (fr < fv[order[2]]) {
      v[order[3]] = reflected, fv[order[3]] = fr;
    } else {
      const Shape contracted = along(0.5);
      const double fc = f(contracted);
      if (fc < fv[order[3]]) {
        v[order[3]] = contracted, fv[order[3]] = fc;
      } else {
        for (std::size_t j = 1; j < 4; ++j) {
          for (std::size_t i = 0; i < 3; ++i)
            v[order[j]][i] = 0.5 * (v[order[j]][i] + v[order[0]][i]);
          fv[order[j]] = f(v[order[j]]);
        }
      }
    }
  }
  return v[static_cast<std::size_t>(std::min_element(fv.begin(), fv.end()) - fv.begin())];
}

// The covariance of the log parameters: the inverse of the negative log-likelihood's Hessian
// (central differences), or nullopt where it is not positive definite (a direction the data
// do not bound).
std::optional<Eigen::Matrix3d> log_covariance(const Series& x, const Shape& z) {
  constexpr double h = 0.05;
  auto f = [&](const Shape& w) { return 0.5 * evaluate(x, w).neg2ll; };
  const double f0 = f(z);
  Eigen::Matrix3d hess;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = i; j < 3; ++j) {
      auto at = [&](double a, double b) {
        Shape w = z;
        w[i] += a * h, w[j] += b * h;
        return f(w);
      };
      hess(i, j) = i == j ? (at(1, 0) - 2.0 * f0 + at(-1, 0)) / (h * h)
                          : (at(1, 1) - at(1, -1) - at(-1, 1) + at(-1, -1)) / (4.0 * h * h);
      hess(j, i) = hess(i, j);
    }
  }
  const Eigen::LLT<Eigen::Matrix3d> llt(hess);
  if (llt.info() != Eigen::Success) return std::nullopt;
  return llt.solve(Eigen::Matrix3d::Identity());
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The process's own part (d, without the constant) smoothed over the rows a trace kept
// (Rauch, Tung & Striebel, AIAA J. 3, 1965): its mean and variance at each row, in units of
// the normalised gain's process and of R.
struct Smoothed {
  std::vector<double> d, var;
};
Smoothed smooth(const Trace& t, const std::vector<Eigen::Matrix2d>& phi) {
  const std::size_t n = t.x_filtered.size();
  Smoothed out;
  out.d.resize(n), out.var.resize(n);
  if (n == 0) return out;
  Eigen::Vector3d x = t.x_filtered[n - 1];
  Eigen::Matrix3d p = t.p_filtered[n - 1];
  out.d[n - 1] = x(0), out.var[n - 1] = p(0, 0);
  for (std::size_t k = n - 1; k-- > 0;) {
    Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
    f.topLeftCorner<2, 2>() = phi[k + 1];
    const Eigen::Matrix3d c = t.p_filtered[k] * f.transpose() *
                              t.p_predicted[k + 1].ldlt().solve(Eigen::Matrix3d::Identity());
    x = t.x_filtered[k] + c * (x - t.x_predicted[k + 1]);
    p = t.p_filtered[k] + c * (p - t.p_predicted[k + 1]) * c.transpose();
    out.d[k] = x(0), out.var[k] = std::max(0.0, p(0, 0));
  }
  return out;
}

}  // namespace

std::string DisturbanceFit::describe() const {
  const double k = spec ? spec->shown_per_unit : 1.0;
  const std::string unit = spec ? spec->unit : "";
  char buf[320];
  std::snprintf(buf, sizeof buf, "%s: %.3g +- %.2g %s RMS over %s %.3g +- %.2g m, mean %.3g %s",
                spec ? spec->name.c_str() : "disturbance", k * rms, k * rms_sd, unit.c_str(),
                periodic ? "a wavelength of" : "a correlation length of", scale_m, scale_sd_m,
                k * mean, unit.c_str());
  return buf;
}

namespace {

// The series the filter runs on: the residual, its gain normalised to an RMS of 1 over the
// calibration rows where it is non-zero (g_rms), each row's step along the row and their median
// (step_m), with the constant's diffuse prior. nullopt where fewer than 50 rows have a gain.
struct Prepared {
  Series x;
  double g_rms = 0.0, step_m = 0.0;
};
std::optional<Prepared> prepare(const std::vector<double>& gain,
                                const std::vector<double>& distance_m,
                                const std::vector<double>& residual, std::size_t calibration_end) {
  const std::size_t n = residual.size();
  double g2 = 0.0, live = 0.0;
  std::size_t first_live = n;
  for (std::size_t k = 0; k < calibration_end; ++k)
    if (gain[k] != 0.0) g2 += gain[k] * gain[k], live += 1.0, first_live = std::min(first_live, k);
  if (live < 50.0) return std::nullopt;
  Prepared out;
  out.g_rms = std::sqrt(g2 / live);
  Series& x = out.x;
  x.e = residual;
  x.g.resize(n);
  x.ds.assign(n, 0.0);
  std::vector<double> steps;
  for (std::size_t k = 0; k < n; ++k) {
    x.g[k] = gain[k] / out.g_rms;
    if (k > 0) x.ds[k] = std::max(0.0, distance_m[k] - distance_m[k - 1]);
    if (k > 0 && x.ds[k] > 0.0) steps.push_back(x.ds[k]);
  }
  x.end = calibration_end;
  x.skip = std::min(calibration_end, first_live + 10);
  double e_max = 0.0, d2 = 0.0;
  for (std::size_t k = 2; k < calibration_end; ++k) {
    e_max = std::max(e_max, std::abs(residual[k]));
    const double d = residual[k] - 2.0 * residual[k - 1] + residual[k - 2];
    d2 += d * d / 6.0;
  }
  const double r0 = std::max(d2 / static_cast<double>(calibration_end), 1e-30);
  x.prior_b = 1e4 * std::max(e_max * e_max, r0) / r0;
  out.step_m = median_of(steps);
  return out;
}

// The size: the RMS the process had over the calibration rows, smoothed, and its SD. A shaping
// filter of one peak fitted to a profile of another spectrum reads its variance with a bias
// (dense rows weigh the spectrum's steep tail), where the smoothed profile itself, at a noise
// well under it, is the profile: E[mean d^2 | rows] = mean(d_s^2 + P_s). Its SD: the variance of
// that mean over the independent stretches the rows hold (one a scale), 4 d^2 P + 2 P^2 each.
void measure_size(const Prepared& prep, const Shape& z, double r, double row_m,
                  DisturbanceFit& out) {
  const Series& x = prep.x;
  const double lambda = std::exp(z[0]), zeta = std::exp(z[1]), g2 = prep.g_rms * prep.g_rms;
  Trace upto;
  upto.keep_states = true;
  const Filtered cal = evaluate(x, z, x.end, &upto);
  out.mean = cal.mean / prep.g_rms;
  const Smoothed sm = smooth(upto, transitions(x, 2.0 * std::numbers::pi / lambda, zeta));
  double ms = 0.0, var = 0.0, rows = 0.0;
  for (std::size_t k = x.skip; k < x.end; ++k)
    ms += sm.d[k] * sm.d[k], var += sm.var[k], rows += 1.0;
  ms /= rows, var /= rows;
  // The states are in the residual's unit over the normalised gain, their variances in R's.
  ms /= g2;
  var *= r / g2;
  out.rms = std::sqrt(ms + var);
  const double stretches = std::max(1.0, row_m / std::max(out.scale_m, prep.step_m));
  out.rms_sd =
      std::sqrt((4.0 * ms * var + 2.0 * var * var) / stretches) / (2.0 * std::max(out.rms, 1e-300));
}

// What the filter over every row says: the calibration rows' standardised innovations'
// whiteness, and the held-out rows' one-step innovations against what the model gives them.
void check_innovations(const Series& x, const Trace& trace, double r, DisturbanceFit& out) {
  std::vector<double> standardised;
  for (std::size_t k = x.skip; k < x.end; ++k)
    standardised.push_back(trace.nu[k] / std::sqrt(trace.s[k]));
  out.whiteness_violations = whiteness_violations(standardised);
  const std::size_t n = trace.nu.size();
  double nu2 = 0.0, s_sum = 0.0;
  for (std::size_t k = x.end; k < n; ++k) nu2 += trace.nu[k] * trace.nu[k], s_sum += trace.s[k];
  const double held = static_cast<double>(n - x.end);
  out.rms_held_out = held > 0 ? std::sqrt(nu2 / held) : 0.0;
  out.predicted_held_out = held > 0 ? std::sqrt(r * s_sum / held) : 0.0;
}

}  // namespace

std::optional<DisturbanceFit> fit_disturbance(const DisturbanceSpec& spec,
                                              const std::vector<double>& gain,
                                              const std::vector<double>& distance_m,
                                              const std::vector<double>& residual,
                                              std::size_t calibration_end,
                                              const DisturbanceFit* near) {
  const std::size_t n = residual.size();
  if (gain.size() != n || distance_m.size() != n || calibration_end < 50 || calibration_end > n)
    return std::nullopt;
  const std::optional<Prepared> prep = prepare(gain, distance_m, residual, calibration_end);
  if (!prep) return std::nullopt;
  const Series& x = prep->x;
  const double row_m = distance_m[calibration_end - 1] - distance_m[0];
  const double step_m = prep->step_m;
  if (!(row_m > 0.0) || !(step_m > 0.0)) return std::nullopt;
  const double lambda_lo = std::max(4.0 * step_m, 1e-4),
               lambda_hi = std::max(2.0 * lambda_lo, 0.5 * row_m);

  // The shape a nearby fit found, its q rescaled to this gain (q is the process's variance
  // over the noise's, the gain normalised), or the grid's best.
  const Shape start = near != nullptr && near->shape.q > 0.0
                          ? Shape{std::log(near->shape.lambda_m), std::log(near->shape.zeta),
                                  std::log(near->shape.q)}
                          : grid_search(x, lambda_lo, lambda_hi);
  const Shape lo{std::log(0.5 * lambda_lo), std::log(0.02), std::log(1e-4)};
  const Shape hi{std::log(2.0 * lambda_hi), std::log(20.0), std::log(1e9)};
  const Shape z = refine(x, start, lo, hi);
  Trace trace;
  const Filtered best = evaluate(x, z, n, &trace);
  const Filtered white = run_filter(x, std::vector<Eigen::Matrix2d>(n, Eigen::Matrix2d::Identity()),
                                    1.0, 0.0, calibration_end, nullptr);

  DisturbanceFit out;
  out.spec = &spec;
  const double lambda = std::exp(z[0]), zeta = std::exp(z[1]), q = std::exp(z[2]);
  out.zeta = zeta;
  out.step_m = step_m;
  out.noise_rms = std::sqrt(best.r);
  out.periodic = zeta < 0.5;
  out.scale_m = out.periodic ? lambda : zeta * lambda / std::numbers::pi;  // 2 zeta / omega
  out.delta_bic =
      best.neg2ll - white.neg2ll + 3.0 * std::log(static_cast<double>(calibration_end - x.skip));
  out.scale_sd_m = std::numeric_limits<double>::infinity();
  if (const auto cov = log_covariance(x, z)) {
    const double var_ln_scale =
        out.periodic ? (*cov)(0, 0) : (*cov)(0, 0) + (*cov)(1, 1) + 2.0 * (*cov)(0, 1);
    out.scale_sd_m = out.scale_m * std::sqrt(std::max(0.0, var_ln_scale));
  }
  measure_size(*prep, z, best.r, row_m, out);
  check_innovations(x, trace, best.r, out);
  out.neg2ll = best.neg2ll;  // summed over the calibration rows whatever rows were filtered
  out.shape.gain = x.g, out.shape.step_m = x.ds;
  out.shape.lambda_m = lambda, out.shape.zeta = zeta, out.shape.q = q;
  out.shape.prior_b = x.prior_b, out.shape.skip = x.skip;
  return out;
}

void standardised_innovations(const DisturbanceFit& d, std::vector<double>& e) {
  const std::size_t n = std::min(e.size(), d.shape.gain.size());
  Series x;
  x.e = e;
  x.g.assign(d.shape.gain.begin(), d.shape.gain.begin() + static_cast<std::ptrdiff_t>(n));
  x.ds.assign(d.shape.step_m.begin(), d.shape.step_m.begin() + static_cast<std::ptrdiff_t>(n));
  x.end = n;
  x.skip = std::min(n, d.shape.skip);
  x.prior_b = d.shape.prior_b;
  // The transitions depend on the shape alone: kept while the steps are the same (a fit calls
  // this thousands of times on one recording). One cache per thread.
  struct Cache {
    std::vector<double> ds;
    double lambda = 0.0, zeta = 0.0;
    std::vector<Eigen::Matrix2d> phi;
  };
  thread_local Cache cache;
  const double omega = 2.0 * std::numbers::pi / d.shape.lambda_m;
  if (cache.ds != x.ds || cache.lambda != d.shape.lambda_m || cache.zeta != d.shape.zeta) {
    cache.ds = x.ds, cache.lambda = d.shape.lambda_m, cache.zeta = d.shape.zeta;
    cache.phi = transitions(x, omega, d.shape.zeta);
  }
  Trace trace;
  run_filter(x, cache.phi, omega, d.shape.q, n, &trace, false);
  for (std::size_t k = 0; k < n; ++k) e[k] = k < x.skip ? 0.0 : trace.nu[k] / std::sqrt(trace.s[k]);
  for (std::size_t k = n; k < e.size(); ++k) e[k] = 0.0;
}

}  // namespace planter::analysis
