// The nip: the lips in series with the stem, by the DEM's reduced law (sim/plant/clamp_nip.h).
#include "sim/plant/clamp_nip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/plant/plant_config.h"
#include "sim/runner/scenario.h"

namespace planter::sim {
namespace {

struct Nip {
  SeedlingForceModel law =
      load_seedling_force_model(std::string(PLANTER_SOURCE_DIR) + "/models/seedling_force.toml");
  DriveModelConfig drive;
  ClampNip nip{law, law.reference_diameter_mm, 0.98, drive.seedling_thickness_gain};
  // The machine's law at the gap, as a reference stem reads it.
  double law_N(double gap_mm) const {
    return gap_mm > 0 ? drive.clamp_k_N * std::pow(gap_mm, drive.clamp_n) : 0.0;
  }
  NipStem stem(double d_mm, double peak_N = 1e9) const { return {d_mm, 0.98, peak_N, false, 1.0}; }
  double force(double gap_mm, NipStem&& s) const { return force(gap_mm, s); }
  double force(double gap_mm, NipStem& s) const {
    return nip.force_N(gap_mm, drive.clamp_k_N, drive.clamp_n, s, 50.0);
  }
};

TEST(ClampNip, TheReferenceStemReadsTheMachinesLaw) {
  const Nip n;
  for (double gap : {0.5, 2.0, 4.3, 6.0})
    EXPECT_NEAR(n.force(gap, n.stem(n.law.reference_diameter_mm)), n.law_N(gap), 1e-4) << gap;
}

TEST(ClampNip, AThickerStemReadsMoreForceAtTheSamePosition) {
  const Nip n;
  const double gap = 4.0;  // about 80 N on the reference stem
  const double thin = n.force(gap, n.stem(8.3)), ref = n.force(gap, n.stem(10.0)),
               thick = n.force(gap, n.stem(11.4));
  EXPECT_LT(thin, ref - 5.0);
  EXPECT_GT(thick, ref + 5.0);
}

TEST(ClampNip, TheStemsComplianceIsInSeries) {
  // A stem at half the stiffness (held over half the length) gives way more: less force than
  // its thickness alone would give through the law.
  const Nip n;
  NipStem soft = n.stem(10.0);
  soft.load_factor = 0.49;
  const double f = n.force(4.0, soft);
  EXPECT_LT(f, n.law_N(4.0) - 10.0);
  // The two compressions add up to the gap the law sees: the solve's own consistency.
  const double added = n.nip.added_compression_mm(soft, f);
  EXPECT_NEAR(n.law_N(4.0 + added), f, 1e-3);
}

TEST(ClampNip, ACollapsingStemShowsTheDrop) {
  const Nip n;
  NipStem s = n.stem(10.0, 100.0);  // its wall gives at 100 N
  const double before = n.force(4.3, s);
  ASSERT_LT(before, 100.0);
  EXPECT_FALSE(s.collapsed);
  const double at = n.force(4.8, s);  // past the peak: the wall collapses
  EXPECT_TRUE(s.collapsed);
  EXPECT_LT(at, 100.0);
  EXPECT_LT(at, before);  // more closure, less force: the drop the load cell sees
  EXPECT_GE(at, n.law.residual_fraction * 100.0 - 1e-6);
  // Closed further, the flattened wall stiffens again.
  EXPECT_GT(n.force(6.0, s), at);
}

// While the lips close on a thick stem, it adds its share; half in, half its thickness.
TEST(ClampNip, AStemComingInAddsItsShare) {
  const Nip n;
  const double gap = 4.0;
  NipStem half = n.stem(12.0);
  half.share = 0.5;
  const double empty = n.force(gap, n.stem(10.0)), full = n.force(gap, n.stem(12.0));
  const double partly = n.force(gap, half);
  EXPECT_GT(partly, empty + 5.0);
  EXPECT_LT(partly, full - 5.0);
  NipStem none = n.stem(12.0);
  none.share = 0.0;
  EXPECT_NEAR(n.force(gap, none), empty, 1e-4);  // not yet touched: the law alone
}

// The stem carries the nip's force in its share: partly in, it holds a force past its peak.
TEST(ClampNip, AStemPartlyInCarriesItsShareOfTheForce) {
  const Nip n;
  NipStem s = n.stem(10.0, 100.0);
  s.share = 0.5;
  const double f = n.force(5.5, s);  // some 120 N through the nip
  ASSERT_GT(f, 100.0);
  EXPECT_FALSE(s.collapsed);
  s.share = 1.0;
  n.force(5.5, s);
  EXPECT_TRUE(s.collapsed);
}

TEST(ClampNip, NoContactReadsNothing) {
  const Nip n;
  EXPECT_EQ(n.force(-6.0, n.stem(10.0)), 0.0);
  EXPECT_EQ(n.force(-1.0, n.stem(8.3)), 0.0);  // a thin stem is not yet touched
}

}  // namespace
}  // namespace planter::sim
