#pragma once
// The seedlings' strength from the paper's measurements: the first peak of the radial
// compression test (the paper, Sec. 3.5: INSTRON-3344, 100 mm/min, six valid specimens).
// The strength model is fitted to these six values only. (The paper's text also gives 140.6 N
// as "the actual maximum radial compression force", the target of its DEM calibration; it is
// not the mean of the six, 161.9 N, and is kept as a comparison, not as the strength.)
//
// Form: lognormal, with the mean and SD of the six. Strength is positive and a failure load's
// spread grows with its size, which a normal law gets wrong in its lower tail, where damage
// happens; six values cannot tell the two apart (their logs' skewness is within the noise),
// so the choice is an assumption and the damage rate depends on it (model_values.cpp ranks it).
#include <array>
#include <cmath>

namespace planter::config {

inline constexpr std::array<double, 6> kMeasuredPeaks_N{181.2, 191.6, 162.9, 137.5, 127.2, 171.1};
inline constexpr double kPaperStatedStrength_N = 140.6;  // the paper's text, for comparison

struct StrengthFit {
  double mean_N = 0, sd_N = 0;  // sample mean and SD (n - 1)
  double min_N = 0, max_N = 0;  // the measured range
  // The 95 % interval of the mean from six values (Student's t, 5 df: 2.571).
  double mean_lo_N = 0, mean_hi_N = 0;
};

inline StrengthFit fit_measured_strength() {
  StrengthFit f;
  double sum = 0, sq = 0;
  f.min_N = kMeasuredPeaks_N[0];
  f.max_N = kMeasuredPeaks_N[0];
  for (double x : kMeasuredPeaks_N) {
    sum += x;
    f.min_N = std::fmin(f.min_N, x);
    f.max_N = std::fmax(f.max_N, x);
  }
  const double n = static_cast<double>(kMeasuredPeaks_N.size());
  f.mean_N = sum / n;
  for (double x : kMeasuredPeaks_N) sq += (x - f.mean_N) * (x - f.mean_N);
  f.sd_N = std::sqrt(sq / (n - 1.0));
  const double half = 2.571 * f.sd_N / std::sqrt(n);
  f.mean_lo_N = f.mean_N - half;
  f.mean_hi_N = f.mean_N + half;
  return f;
}

// The fit, made once.
inline const StrengthFit& measured_strength() {
  static const StrengthFit fit = fit_measured_strength();
  return fit;
}

// A lognormal strength with this mean and SD, from one standard normal draw z.
inline double lognormal_strength_N(double mean_N, double sd_N, double z) {
  const double s2 = std::log1p((sd_N / mean_N) * (sd_N / mean_N));
  return std::exp(std::log(mean_N) - 0.5 * s2 + std::sqrt(s2) * z);
}

}  // namespace planter::config
