#include "sim/plant/clamp_nip.h"

#include <algorithm>
#include <cmath>

namespace planter::sim {
namespace {
constexpr double kForceMaxN = 1e6;    // past any clamp: the bracket's top
constexpr double kToleranceN = 1e-6;  // the solve's resolution, below the load cell's bits
constexpr int kIterationsMax = 80;    // bisection alone reaches 1e-6 N from 1e6 N in 40
constexpr double kForceMinN = 1e-9;   // where the power laws' slopes are taken near zero
}  // namespace

// The DEM's law at the nip's scale: the stem carries F where the test's specimen carries F / a.
double ClampNip::intact_compression_mm(double d_mm, double a, double force_N) const {
  return law_.compression_mm(d_mm, force_N / a);
}

double ClampNip::stem_compression_mm(const NipStem& stem, double force_N) const {
  return stem_compression(stem, force_N).mm;
}

double ClampNip::added_compression_mm(const NipStem& stem, double force_N) const {
  return stem.share * (gain_ * (stem.diameter_mm - ref_d_mm_) - stem_compression_mm(stem, force_N) +
                       intact_compression_mm(ref_d_mm_, ref_a_, force_N));
}

// The stem's compression at F, the intact branch or past its collapse, and its slope
// d(delta)/dF: a power law's slope is (1/m) delta / F (taken at kForceMinN near zero).
ClampNip::Compression ClampNip::stem_compression(const NipStem& stem, double force_N) const {
  const double m = law_.exponent;
  const double slope_at_N = std::max(force_N, kForceMinN);
  if (!stem.collapsed) {
    const double delta = intact_compression_mm(stem.diameter_mm, stem.load_factor, force_N);
    return {delta, delta / (m * slope_at_N)};
  }
  const double peak_mm = intact_compression_mm(stem.diameter_mm, stem.load_factor, stem.peak_N);
  const double residual_N = law_.residual_fraction * stem.peak_N;
  if (force_N <= residual_N) {  // unloading below the residual: back along the intact form
    const double delta = peak_mm * std::pow(std::max(0.0, force_N) / residual_N, 1.0 / m);
    return {delta, delta / (m * slope_at_N)};
  }
  const double above_N = force_N - residual_N;
  const double rise = intact_compression_mm(stem.diameter_mm, stem.load_factor, above_N);
  return {peak_mm + rise, rise / (m * above_N)};
}

double ClampNip::force_N(double gap_mm, double k_N, double n, NipStem& stem, double guess_N) const {
  // h(F) = the gap the law sees with this stem, less the law's compression at F; its root is
  // the force. h(0) is the gap with the stem's thickness (no force, no compression): the lips
  // touch when it is positive. h falls as F rises (the law's compression grows faster than the
  // two stems' difference), so Newton from the last step's force, kept inside the bracket
  // [lo, hi] that the signs of h build, converges in a few steps; bisection where it would leave.
  const double share = stem.share;
  const double touch_mm = gap_mm + share * gain_ * (stem.diameter_mm - ref_d_mm_);
  if (touch_mm <= 0.0) return 0.0;
  auto solve = [&]() {
    double lo = 0.0, hi = kForceMaxN;
    double f = std::clamp(guess_N, kForceMinN, hi);
    for (int i = 0; i < kIterationsMax; ++i) {
      const Compression stem_c = stem_compression(stem, f);
      const double ref_mm = intact_compression_mm(ref_d_mm_, ref_a_, f);
      const double law_mm = std::pow(f / k_N, 1.0 / n);
      const double hf = touch_mm - share * (stem_c.mm - ref_mm) - law_mm;
      const double slope =
          share * (-stem_c.mm_per_N + ref_mm / (law_.exponent * f)) - law_mm / (n * f);
      if (hf > 0.0)
        lo = f;
      else
        hi = f;
      double next = slope < 0.0 ? f - hf / slope : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      const bool done = std::abs(next - f) < kToleranceN || hi - lo < kToleranceN;
      f = next;
      if (done) break;
    }
    return f;
  };
  double f = solve();
  // The stem carries the nip's force in its share; the rest passes from lip to lip beside it.
  if (!stem.collapsed && share * f > stem.peak_N) {
    stem.collapsed = true;  // the wall gives: the same gap now carries less
    f = solve();
  }
  return f;
}

}  // namespace planter::sim
