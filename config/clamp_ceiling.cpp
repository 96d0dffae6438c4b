#include "config/clamp_ceiling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "config/stem_strength.h"

namespace planter::config {

double held_length_mm(double contact_area_mm2, double band_mm, double diameter_mm) {
  return std::min(contact_area_mm2 / std::max(0.1, diameter_mm), band_mm);
}

double normal_quantile(double p) {
  // Bisection on Phi(z) = erfc(-z / sqrt 2) / 2, which rises with z: exact to 1e-12 in z within
  // [-40, 40] in 60 halvings, run once at load time.
  const double target = std::clamp(p, 1e-300, 1.0 - 1e-16);
  double lo = -40.0, hi = 40.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (0.5 * std::erfc(-mid / std::sqrt(2.0)) < target)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

double clamp_ceiling_N(const ClampCeilingRule& rule, double diameter_mm) {
  const StrengthFit& m = measured_strength();
  const double z = normal_quantile(rule.stems_past_peak_pct / 100.0);
  const double test_N = lognormal_strength_N(m.mean_N, m.sd_N, z);
  return test_N * held_length_mm(rule.contact_area_mm2, rule.band_mm, diameter_mm) /
         rule.specimen_length_mm;
}

std::string clamp_ceiling_derivation(const ClampCeilingRule& rule, double diameter_mm) {
  const StrengthFit& m = measured_strength();
  const double z = normal_quantile(rule.stems_past_peak_pct / 100.0);
  const double held_mm = held_length_mm(rule.contact_area_mm2, rule.band_mm, diameter_mm);
  char line[512];
  std::snprintf(line, sizeof line,
                "clamp ceiling %.1f N: %g %% of %g mm stems pass their first peak there (the "
                "paper's six peaks, lognormal, mean %.1f N SD %.1f N: %.1f N at that share, "
                "over a %g mm specimen (assumed), held over %.1f mm in the lips)",
                clamp_ceiling_N(rule, diameter_mm), rule.stems_past_peak_pct, diameter_mm, m.mean_N,
                m.sd_N, lognormal_strength_N(m.mean_N, m.sd_N, z), rule.specimen_length_mm,
                held_mm);
  return line;
}

}  // namespace planter::config
