#include "dem/reduced_order.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <stdexcept>

#include "dem/parallel_for.h"

namespace planter::dem {
namespace {

constexpr double kSeating_mm = 0.3;

struct Branch {
  std::vector<double> delta_mm, force_N;
};

// The elastic branch: from the seating to 90 % of the way to the first peak.
Branch elastic_branch(const CompressionResult& r) {
  Branch b;
  const double end_mm = 0.9 * r.peak_displacement_m * 1e3;
  for (const auto& p : r.curve) {
    const double d = p.displacement_m * 1e3;
    if (d >= kSeating_mm && d <= end_mm && p.force_N > 0.0) {
      b.delta_mm.push_back(d);
      b.force_N.push_back(p.force_N);
    }
  }
  return b;
}

// Least-squares line y = a + b x.
void line_fit(const std::vector<double>& x, const std::vector<double>& y, double& a, double& b) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sx += x[k];
    sy += y[k];
    sxx += x[k] * x[k];
    sxy += x[k] * y[k];
  }
  const double den = n * sxx - sx * sx;
  b = std::abs(den) > 1e-300 ? (n * sxy - sx * sy) / den : 0.0;
  a = n > 0 ? (sy - b * sx) / n : 0.0;
}

// The compressions to run: each diameter (its discretisation scaled with it, so that every
// diameter's wall is the same rings of particles: with a fixed 1.5 mm particle an 8.3 mm
// seedling's inner ring shrinks to 3 particles and it squashes flat without collapsing, a jump
// of the model, not of the seedling), then the reference loaded at its speed and twice as fast
// (for the damping).
std::vector<CompressionSetup> compression_setups(const CompressionSetup& base,
                                                 const std::vector<double>& diameters_mm) {
  std::vector<CompressionSetup> setups;
  for (double d : diameters_mm) {
    const double scale = d * 1e-3 / base.seedling.diameter_m;
    CompressionSetup s = base;
    s.seedling.diameter_m = d * 1e-3;
    s.seedling.particle_radius_m *= scale;
    s.seedling.bond_gap_m *= scale;
    s.bonds.radius_m *= scale;
    setups.push_back(s);
  }
  CompressionSetup fast = base;
  fast.speedup = 2.0 * base.speedup;
  setups.push_back(base);
  setups.push_back(fast);
  return setups;
}

// The exponent: log F = log k + n log delta on each collapsing curve's elastic branch; n is
// their mean (1 where none collapses).
double elastic_exponent(const std::vector<CompressionResult>& results, std::size_t curves) {
  std::vector<double> exponents;
  for (std::size_t k = 0; k < curves; ++k) {
    const Branch b = elastic_branch(results[k]);
    if (b.delta_mm.size() < 3) continue;
    std::vector<double> lx, ly;
    for (std::size_t i = 0; i < b.delta_mm.size(); ++i) {
      lx.push_back(std::log(b.delta_mm[i]));
      ly.push_back(std::log(b.force_N[i]));
    }
    double a = 0, n = 1;
    line_fit(lx, ly, a, n);
    if (results[k].first_peak_found) exponents.push_back(n);
  }
  double n_sum = 0;
  for (double n : exponents) n_sum += n;
  return exponents.empty() ? 1.0 : n_sum / static_cast<double>(exponents.size());
}

// k with n fixed, minimising sum (F - k delta^n)^2 over the elastic branch, and the fit's RMS.
std::pair<double, double> stiffness_at(const Branch& b, double exponent) {
  double num = 0, den = 0;
  for (std::size_t i = 0; i < b.delta_mm.size(); ++i) {
    const double x = std::pow(b.delta_mm[i], exponent);
    num += b.force_N[i] * x;
    den += x * x;
  }
  const double k_fit = den > 0 ? num / den : 0.0;
  double ss = 0;
  for (std::size_t i = 0; i < b.delta_mm.size(); ++i) {
    const double e = b.force_N[i] - k_fit * std::pow(b.delta_mm[i], exponent);
    ss += e * e;
  }
  return {k_fit, b.delta_mm.empty() ? 0.0 : std::sqrt(ss / static_cast<double>(b.delta_mm.size()))};
}

// After the peak: the lowest force over the next millimetre (the trough of the partial drop,
// before the wall densifies), or infinity where the curve has no point there.
double trough_after_peak_N(const CompressionResult& r) {
  double trough = std::numeric_limits<double>::infinity();
  const double dp = r.peak_displacement_m * 1e3;
  for (const auto& p : r.curve) {
    const double d = p.displacement_m * 1e3;
    if (d > dp && d <= dp + 1.0) trough = std::min(trough, p.force_N);
  }
  return trough;
}

// The stiffness, first peak and its displacement as lines in the diameter, and the residual
// after the collapse as the peaks' mean share.
void fit_diameter_lines(const std::vector<double>& diameters_mm,
                        const std::vector<CompressionResult>& results, ReducedOrderFit& fit) {
  sim::SeedlingForceModel& m = fit.model;
  std::vector<double> ds, ks, fps, dps, residuals;
  for (std::size_t k = 0; k < diameters_mm.size(); ++k) {
    DiameterCurve dc;
    dc.diameter_mm = diameters_mm[k];
    dc.result = results[k];
    const auto [k_fit, rms_N] = stiffness_at(elastic_branch(dc.result), m.exponent);
    dc.fit_rms_N = rms_N;
    const double trough = trough_after_peak_N(dc.result);
    const double fp = dc.result.peak_force_N;
    if (dc.result.first_peak_found && std::isfinite(trough) && fp > 0)
      residuals.push_back(std::max(0.0, trough) / fp);
    fit.curves.push_back(dc);
    // A curve with no collapse within the stroke (a thin seedling squashed flat) has no peak
    // to fit: it is reported, not averaged in.
    if (!dc.result.first_peak_found) continue;
    ds.push_back(dc.diameter_mm);
    ks.push_back(k_fit);
    fps.push_back(fp);
    dps.push_back(dc.result.peak_displacement_m * 1e3);
  }
  if (ds.empty()) throw std::runtime_error("no DEM curve has a first peak: nothing to reduce");
  std::vector<double> dx;
  for (double d : ds) dx.push_back(d - m.reference_diameter_mm);
  line_fit(dx, ks, m.stiffness_N_per_mm_n, m.stiffness_slope_per_mm);
  line_fit(dx, fps, m.peak_force_N, m.peak_force_slope_N_per_mm);
  line_fit(dx, dps, m.peak_displacement_mm, m.peak_displacement_slope);
  double rsum = 0;
  for (double r : residuals) rsum += r;
  m.residual_fraction =
      residuals.empty() ? 1.0 : std::min(1.0, rsum / static_cast<double>(residuals.size()));
}

// Damping: the force difference between the two loading speeds on the elastic branch, per
// unit of the speeds' difference.
double damping_N_s_per_mm(const CompressionSetup& slow, const CompressionResult& rs,
                          const CompressionSetup& fast, const CompressionResult& rf) {
  const double v_slow = slow.platen_speed_mps * slow.speedup * 1e3;
  const double v_fast = fast.platen_speed_mps * fast.speedup * 1e3;
  double dsum = 0;
  int dn = 0;
  const double end_mm = 0.9 * std::min(rs.peak_displacement_m, rf.peak_displacement_m) * 1e3;
  for (std::size_t i = 0; i < rs.curve.size() && i < rf.curve.size(); ++i) {
    const double d = rs.curve[i].displacement_m * 1e3;
    if (d < kSeating_mm || d > end_mm) continue;
    dsum += rf.curve[i].force_N - rs.curve[i].force_N;
    ++dn;
  }
  return dn > 0 ? std::max(0.0, dsum / dn / (v_fast - v_slow)) : 0.0;
}

}  // namespace

ReducedOrderFit fit_reduced_order(
    const CompressionSetup& base, const std::vector<double>& diameters_mm, int jobs,
    const std::function<void(std::size_t done, std::size_t total)>& on_run_done) {
  ReducedOrderFit fit;
  sim::SeedlingForceModel& m = fit.model;
  m.reference_diameter_mm = base.seedling.diameter_m * 1e3;
  const std::vector<CompressionSetup> setups = compression_setups(base, diameters_mm);
  std::vector<CompressionResult> results(setups.size());
  std::mutex progress;
  std::size_t done = 0;
  parallel_for(setups.size(), jobs, [&](std::size_t k) {
    results[k] = run_compression(setups[k]);
    if (on_run_done) {
      const std::lock_guard<std::mutex> lock(progress);
      on_run_done(++done, setups.size());
    }
  });
  m.exponent = elastic_exponent(results, diameters_mm.size());
  fit_diameter_lines(diameters_mm, results, fit);
  const std::size_t slow = setups.size() - 2, fast = setups.size() - 1;
  m.damping_N_s_per_mm =
      damping_N_s_per_mm(setups[slow], results[slow], setups[fast], results[fast]);
  fit.damping_runs_speedups[0] = setups[slow].speedup;
  fit.damping_runs_speedups[1] = setups[fast].speedup;
  m.loaded = true;
  return fit;
}

std::string reduced_order_toml(const ReducedOrderFit& fit, const std::string& source) {
  const sim::SeedlingForceModel& m = fit.model;
  char buf[1600];
  std::snprintf(buf, sizeof buf,
                "# Seedling radial force, reduced from the bonded-particle DEM by planter-dem "
                "reduce.\n# %s\n# F = k(d) delta^n + c delta_dot up to F_p(d) at delta_p(d); "
                "then the wall collapses to residual_fraction F_p.\n"
                "[seedling_force]\nreference_diameter_mm = %.6g\nexponent = %.6g\n"
                "stiffness_N_per_mm_n = %.6g\nstiffness_slope_per_mm = %.6g\n"
                "peak_force_N = %.6g\npeak_force_slope_N_per_mm = %.6g\n"
                "peak_displacement_mm = %.6g\npeak_displacement_slope = %.6g\n"
                "residual_fraction = %.6g\ndamping_N_s_per_mm = %.6g\n",
                source.c_str(), m.reference_diameter_mm, m.exponent, m.stiffness_N_per_mm_n,
                m.stiffness_slope_per_mm, m.peak_force_N, m.peak_force_slope_N_per_mm,
                m.peak_displacement_mm, m.peak_displacement_slope, m.residual_fraction,
                m.damping_N_s_per_mm);
  return buf;
}

}  // namespace planter::dem
