// The disturbance process (analysis/disturbance.h) read back from a synthetic residual: a
// terrain of known RMS and wavelength along a row driven at a wandering speed with stops, seen
// through a gain, under white noise.
#include "analysis/disturbance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace planter::analysis;

namespace {

struct Row {
  std::vector<double> distance_m, gain, residual, profile;
};

// A sum of 40 sinusoids of random phase around `wavelength_m` (a random profile of that
// dominant wavelength, RMS `rms`), under white noise `noise`, seen through gain -1 (the
// terrain adds to the depth), at 8 rows a second, 0.06 m/s +- 8 %, stopped for 8 s twice.
Row terrain_row(double rms, double wavelength_m, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  std::normal_distribution<double> spread(0.0, 0.15), white(0.0, noise);
  std::vector<std::pair<double, double>> waves;  // wavenumber, phase
  for (int i = 0; i < 40; ++i)
    waves.emplace_back(2.0 * std::numbers::pi / (wavelength_m * std::exp(spread(rng))), phase(rng));
  Row r;
  double s = 0.0;
  for (int k = 0; k < 6000; ++k) {
    const double t = k / 8.0;
    const bool stopped = (t > 200.0 && t < 208.0) || (t > 500.0 && t < 508.0);
    if (k > 0 && !stopped) s += 0.06 * (1.0 + 0.08 * std::sin(t / 23.0)) / 8.0;
    double d = 0.0;
    for (const auto& [kappa, phi] : waves) d += std::sin(kappa * s + phi);
    d *= rms / std::sqrt(20.0);
    r.distance_m.push_back(s);
    r.gain.push_back(-1.0);
    r.residual.push_back(-d + white(rng));
    r.profile.push_back(d);
  }
  return r;
}

}  // namespace

TEST(Disturbance, ATerrainIsReadWithItsSizeAndWavelength) {
  const DisturbanceSpec spec{"terrain under the depth wheel", "mm", 1.0};
  for (unsigned seed : {1u, 2u, 3u}) {
    const Row row = terrain_row(1.0, 0.45, 0.01, seed);
    const auto d = fit_disturbance(spec, row.gain, row.distance_m, row.residual, 4200);
    ASSERT_TRUE(d.has_value());
    // The profile's own RMS over the calibration rows (a sum of 40 waves is not exactly 1).
    double sum = 0.0;
    for (std::size_t k = 0; k < 4200; ++k) sum += row.profile[k] * row.profile[k];
    const double truth = std::sqrt(sum / 4200.0);
    EXPECT_NEAR(d->rms, truth, 3.0 * d->rms_sd) << d->describe();
    EXPECT_TRUE(d->periodic) << d->describe();
    // The profile's wavelengths spread by 15 % about 0.45 m.
    EXPECT_NEAR(d->scale_m, 0.45, 0.05) << d->describe();
    EXPECT_LT(d->delta_bic, -100.0);
    // One step ahead, the held-out rows are left at about the noise and what the process's
    // own step adds, as the process says.
    EXPECT_LT(d->rms_held_out, 1.5 * d->predicted_held_out) << d->describe();
    EXPECT_LT(d->rms_held_out, 0.2 * truth) << d->describe();
  }
}

TEST(Disturbance, WhiteNoiseAloneEarnsNothing) {
  const DisturbanceSpec spec{"terrain under the depth wheel", "mm", 1.0};
  const Row row = terrain_row(0.0, 0.45, 0.01, 4);
  const auto d = fit_disturbance(spec, row.gain, row.distance_m, row.residual, 4200);
  ASSERT_TRUE(d.has_value());
  EXPECT_GT(d->delta_bic, -20.0) << d->describe();
}

TEST(Disturbance, TooFewRowsSayNothing) {
  const DisturbanceSpec spec{"terrain under the depth wheel", "mm", 1.0};
  const Row row = terrain_row(1.0, 0.45, 0.01, 5);
  EXPECT_FALSE(fit_disturbance(spec, row.gain, row.distance_m, row.residual, 40).has_value());
  const std::vector<double> zero(row.gain.size(), 0.0);
  EXPECT_FALSE(fit_disturbance(spec, zero, row.distance_m, row.residual, 4200).has_value());
}
