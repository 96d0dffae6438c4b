// The calibrated seedling in the paper's compression test: 21000 DEM steps, seconds in a
// release build and many minutes under the sanitizers, so its own target (label
// release_only: the release ctest runs it; the sanitizer ctest leaves it to that run).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "dem/compression_test.h"
#include "dem/dem_params.h"

using namespace planter::dem;

// The calibrated seedling (models/seedling_dem.toml) in the paper's compression test: a first
// peak near the measured one, a partial drop, then densification; quasi-static throughout; and
// it stays one body, with under a third of its bonds broken at 6 mm.
TEST(CompressionTest, TheCalibratedSeedlingCracksAndStaysOneBody) {
  CompressionSetup s =
      load_compression_setup(std::string(PLANTER_SOURCE_DIR) + "/models/seedling_dem.toml");
  s.stroke_m = 6.0e-3;
  const CompressionResult r = run_compression(s);
  ASSERT_TRUE(r.first_peak_found);
  EXPECT_NEAR(r.peak_force_N, 140.6, 14.06);           // within 10 %
  EXPECT_NEAR(r.peak_displacement_m * 1e3, 4.0, 1.0);  // "about 4 mm"
  EXPECT_LT(r.max_kinetic_to_work, 0.05);              // quasi-static
  EXPECT_LT(r.broken_bonds, r.bonds / 3) << "bonds broken at 6 mm";
  double trough = r.peak_force_N, last = 0.0;
  for (const auto& p : r.curve) {
    if (p.displacement_m > r.peak_displacement_m && p.displacement_m < r.peak_displacement_m + 1e-3)
      trough = std::min(trough, p.force_N);
    last = p.force_N;
  }
  EXPECT_LT(trough, 0.9 * r.peak_force_N) << "no drop after the peak";
  EXPECT_GT(trough, 0.3 * r.peak_force_N) << "the wall should not give way entirely";
  EXPECT_GT(last, r.peak_force_N) << "no densification";
}
