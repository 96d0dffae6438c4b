#pragma once
// The sizes of a residual the analysis compares: RMS over a span, and white measurement noise.
#include <cmath>
#include <cstddef>
#include <vector>

namespace planter::analysis {

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

}  // namespace planter::analysis
