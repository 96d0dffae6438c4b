#pragma once
// The sizes of a residual the analysis compares: RMS over a span, and white measurement noise.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace planter::analysis {

// The residual pred - y, row by row.
inline std::vector<double> residual_of(const std::vector<double>& pred,
                                       const std::vector<double>& y) {
  std::vector<double> e(y.size());
  for (std::size_t k = 0; k < y.size(); ++k) e[k] = pred[k] - y[k];
  return e;
}

// RMS of a - b over samples [from, to).
inline double rms_between(const std::vector<double>& a, const std::vector<double>& b,
                          std::size_t from, std::size_t to) {
  double s = 0;
  for (std::size_t k = from; k < to; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return to > from ? std::sqrt(s / static_cast<double>(to - from)) : 0.0;
}

// RMS of e over samples [from, to).
inline double rms_between(const std::vector<double>& e, std::size_t from, std::size_t to) {
  double s = 0;
  for (std::size_t k = from; k < to; ++k) s += e[k] * e[k];
  return to > from ? std::sqrt(s / static_cast<double>(to - from)) : 0.0;
}

// White noise in samples [0, end) from second differences: a slow trend or a slow tone hardly
// changes them, and white noise of variance s^2 gives second differences of variance 6 s^2.
inline double white_noise_rms(const std::vector<double>& y, std::size_t end) {
  double s = 0;
  std::size_t n = 0;
  for (std::size_t k = 2; k < end; ++k) {
    const double d2 = y[k] - 2.0 * y[k - 1] + y[k - 2];
    s += d2 * d2;
    ++n;
  }
  return n > 0 ? std::sqrt(s / static_cast<double>(n) / 6.0) : 0.0;
}

// The spacing of the grid a signal's values lie on: the median gap between its distinct values
// (a quantised sensor's step, or a tiny gap for a continuous one).
inline double value_grid(const std::vector<double>& y) {
  std::vector<double> v = y;
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  std::vector<double> gaps;
  for (std::size_t k = 1; k < v.size(); ++k) gaps.push_back(v[k] - v[k - 1]);
  if (gaps.empty()) return 0.0;
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2),
                   gaps.end());
  return gaps[gaps.size() / 2];
}

// How many of y's values are exactly its largest.
inline std::size_t rows_at_top(const std::vector<double>& y) {
  if (y.empty()) return 0;
  const double top = *std::max_element(y.begin(), y.end());
  return static_cast<std::size_t>(std::count(y.begin(), y.end(), top));
}

// The RMS error a sensor's resolution alone leaves: rounding to a step q is an error spread
// evenly over +-q/2, of standard deviation q / sqrt(12) (the resolution of a digital
// indication, JCGM 100:2008 "GUM", F.2.2.1). No model matches a recording closer than that,
// however quiet the sensor: a steady force read in 2 N steps shows no noise to second
// differences, yet its rounding is up to 1 N either way.
inline double resolution_rms(double step) { return step / std::sqrt(12.0); }

// The share of lags 1-50 at which v's sample autocorrelation lies outside +-1.96 / sqrt(N): the
// sample autocorrelation about the whole series' mean over its whole variance, and the band a
// white series' stays in at 95 % (Box & Jenkins, "Time Series Analysis", sec. 2.1.6 and 6.2.2,
// Bartlett's approximation). A model that explains a residual leaves it white. 0 for a series
// under 60 values or without variance.
inline double whiteness_violations(const std::vector<double>& v) {
  const std::size_t n = v.size();
  if (n < 60) return 0.0;
  double mean = 0.0;
  for (double x : v) mean += x / static_cast<double>(n);
  double var = 0.0;
  for (double x : v) var += (x - mean) * (x - mean);
  if (!(var > 0.0)) return 0.0;
  const double band = 1.96 / std::sqrt(static_cast<double>(n));
  int outside = 0;
  for (std::size_t lag = 1; lag <= 50; ++lag) {
    double c = 0.0;
    for (std::size_t k = lag; k < n; ++k) c += (v[k] - mean) * (v[k - lag] - mean);
    outside += std::abs(c / var) > band;
  }
  return outside / 50.0;
}

}  // namespace planter::analysis
