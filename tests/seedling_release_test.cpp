// The release mechanics (sim/plant/seedling_release.h): each stage moves the seedling the way
// its force says, and the soil's hold is Broms' with Rankine's coefficient.
#include "sim/plant/seedling_release.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "config/stem_strength.h"

namespace planter::sim {
namespace {

ReleaseInput centre(double sigma) {
  ReleaseInput in;
  in.length_mm = 196.0;
  in.diameter_mm = 10.0;
  in.v_mps = 0.06;
  in.omega_radps = sigma * in.v_mps / PlantConfig{}.disc_radius_m;
  in.depth_mm = 102.0;
  in.clamp_force_N = 90.0;
  return in;
}

TEST(RootAnchorage, IsBromsShortPileWithRankinesCoefficient) {
  const soil::Soil loam{14.0, 30.0, 0.0};  // 14 kN/m^3, 30 deg: K_p = 3
  EXPECT_NEAR(soil::passive_coefficient(loam), 3.0, 1e-9);
  const soil::RootAnchorage hold(loam);
  // 0.5 K_p gamma D b^3 for a 10 mm root buried 50 mm.
  EXPECT_NEAR(hold.holding_moment_Nm(0.010, 0.050), 0.5 * 3 * 14000 * 0.010 * 1.25e-4, 1e-12);
  // The same moment through a load 20 mm above the surface: over the lever e + b.
  EXPECT_NEAR(hold.holding_force_N(0.010, 0.050, 0.020),
              hold.holding_moment_Nm(0.010, 0.050) / 0.070, 1e-12);
  EXPECT_NEAR(hold.plowing_force_N(0.010, 0.050), 1.5 * 3 * 14000 * 0.010 * 2.5e-3, 1e-12);
  EXPECT_NEAR(hold.plowing_depth_m(0.010, 0.050), 2.0 * 0.050 / 3.0, 1e-12);
  EXPECT_EQ(hold.holding_moment_Nm(0.010, 0.0), 0.0);
}

TEST(RootAnchorage, CohesionAddsRankineBellsTermAndAFewKilopascalsHoldTenTimesMore) {
  const soil::Soil loose{14.0, 30.0, 0.0}, moist{14.0, 30.0, 3.0};
  const soil::RootAnchorage c0(loose), c3(moist);
  // 3 D (2 c sqrt(K_p)) b^2 / 2 more about the end, 3 D (2 c sqrt(K_p)) b more when plowed.
  const double cohesive = 2.0 * 3000.0 * std::sqrt(3.0);
  EXPECT_NEAR(c3.holding_moment_Nm(0.010, 0.040) - c0.holding_moment_Nm(0.010, 0.040),
              1.5 * cohesive * 0.010 * 0.040 * 0.040, 1e-12);
  EXPECT_NEAR(c3.plowing_force_N(0.010, 0.040) - c0.plowing_force_N(0.010, 0.040),
              3.0 * cohesive * 0.010 * 0.040, 1e-12);
  EXPECT_GT(c3.holding_moment_Nm(0.010, 0.040), 10.0 * c0.holding_moment_Nm(0.010, 0.040));
}

TEST(SeedlingRelease, TheDiscRidesWithTheOpenerSoTheBurialFollowsTheDepth) {
  const PlantConfig config;
  ReleaseInput in = centre(1.5);
  in.depth_mm = 80.0;
  const double shallow = release_seedling(config, in).burial_mm;
  in.depth_mm = 140.0;
  const double deep = release_seedling(config, in).burial_mm;
  EXPECT_NEAR(deep - shallow, 60.0, 1.0) << shallow << " " << deep;
  // Its lowest point sits root_clearance_mm above the floor, 10 deg before the release.
  EXPECT_LT(deep, 140.0 - config.mechanism.root_clearance_mm);
}

TEST(SeedlingRelease, TooLittleGripDropsTheSeedlingInTheCarry) {
  const PlantConfig config;
  ReleaseInput in = centre(1.5);
  const double needed = carry_grip_needed_N(config, in.length_mm, in.diameter_mm, in.omega_radps);
  // A 196 mm, 10 mm seedling weighs about 0.13 N; over 2 x 0.25 of friction, with the hand-off.
  EXPECT_GT(needed, 0.2);
  EXPECT_LT(needed, 1.0);
  in.clamp_force_N = 0.9 * needed;
  EXPECT_TRUE(release_seedling(config, in).fell_in_carry);
  in.clamp_force_N = 1.1 * needed;
  EXPECT_FALSE(release_seedling(config, in).fell_in_carry);
}

TEST(SeedlingRelease, AWeakGripLetsTheSoilSlideTheSeedlingAlongTheClamp) {
  PlantConfig config;
  config.soil.backflow.cohesion_kPa = 2.0;
  // A short root end and a wide grip: the soil's moment about the lips is small, so its push
  // along the rod is what beats a weak grip (with 70 mm the seedling turns first).
  config.mechanism.root_protrusion_mm = 12.0;
  config.mechanism.contact_area_mm2 = 400.0;
  ReleaseInput in = centre(1.5);
  in.clamp_force_N = 90.0;
  const double firm = release_seedling(config, in).clamp_slip_mm;
  in.clamp_force_N = 5.0;
  const double weak = release_seedling(config, in).clamp_slip_mm;
  EXPECT_EQ(firm, 0.0);
  EXPECT_LT(weak, -1.0) << "the soil pushes the root back into the clamp";
}

TEST(SeedlingRelease, TheCoveringWheelSavesAFallingSeedlingOnlyIfItComesFirst) {
  PlantConfig config;
  config.soil.backflow.cohesion_kPa = 0.0;
  ReleaseInput in = centre(1.5);
  in.depth_mm = 45.0;  // little returned soil: it cannot stand on it
  in.scatter_deg = 20.0;
  config.mechanism.covering_wheel_behind_mm = 1.0;  // at once
  const ReleaseOutcome early = release_seedling(config, in);
  config.mechanism.covering_wheel_behind_mm = 400.0;  // 6.7 s at 0.06 m/s
  const ReleaseOutcome late = release_seedling(config, in);
  EXPECT_FALSE(early.lodged) << early.tilt_deg;
  EXPECT_TRUE(late.lodged) << late.tilt_deg;
  EXPECT_GT(std::abs(late.fall_deg), std::abs(early.fall_deg));
}

TEST(SeedlingRelease, TheLipsTurnTheTopBackwardsOnlyWhenTheDiscOutrunsTheGround) {
  const PlantConfig config;
  // sigma 1.5: the disc's surface moves backwards over the ground at the lowest point (F').
  EXPECT_LT(release_seedling(config, centre(1.5)).lip_drag_deg, -1.0);
  // sigma 0.6: it moves forwards, and takes the top forwards.
  EXPECT_GT(release_seedling(config, centre(0.6)).lip_drag_deg, 1.0);
}

TEST(SeedlingRelease, TheTiltFallsAsSigmaRisesAndCrossesUprightBetween) {
  const PlantConfig config;
  double previous = 1e9;
  for (double sigma : {0.8, 1.0, 1.2, 1.4, 1.6, 1.8}) {
    const double tilt = release_seedling(config, centre(sigma)).tilt_deg;
    EXPECT_LT(tilt, previous + 1e-9) << "sigma " << sigma;
    previous = tilt;
  }
  EXPECT_GT(release_seedling(config, centre(0.8)).tilt_deg, 0.0);
  EXPECT_LT(release_seedling(config, centre(1.8)).tilt_deg, 0.0);
}

TEST(SeedlingRelease, AShallowFurrowLeavesTooLittleSoilAndTheSeedlingLodges) {
  const PlantConfig config;
  ReleaseInput in = centre(1.8);
  in.depth_mm = 30.0;
  const ReleaseOutcome shallow = release_seedling(config, in);
  EXPECT_TRUE(shallow.lodged);
  EXPECT_NEAR(std::abs(shallow.tilt_deg), 90.0, 1e-9);
  in.depth_mm = 102.0;
  EXPECT_FALSE(release_seedling(config, in).lodged);
}

TEST(SeedlingRelease, AWeakGripLetsTheSoilTurnTheSeedlingInTheClamp) {
  PlantConfig config;
  ReleaseInput in = centre(1.5);
  const double firm = release_seedling(config, in).clamp_turn_deg;
  config.mechanism.contact_area_mm2 = 60.0;  // a narrow grip: friction moment mu N w / 2
  in.clamp_force_N = 30.0;
  const double weak = release_seedling(config, in).clamp_turn_deg;
  EXPECT_LT(weak, firm - 2.0) << "firm " << firm << " weak " << weak;
}

// Before the grip gives, the seedling turns with the lips as far as their rubber shears: the
// elastic turn is the soil's moment over 2 G A (w^2 + d^2) / (12 h), whatever the clamp's
// compression law (which presses the lips together and has no say in their turning).
TEST(SeedlingRelease, TheLipsTurnElasticallyByTheirRubbersShearStiffness) {
  PlantConfig config;
  ReleaseInput in = centre(1.5);
  in.clamp_force_N = 400.0;  // a grip the soil never beats: the turn is elastic alone
  const double base = release_seedling(config, in).clamp_turn_deg;
  ASSERT_GT(std::abs(base), 0.05);
  config.mechanism.lip_shear_modulus_MPa *= 2.0;
  EXPECT_NEAR(release_seedling(config, in).clamp_turn_deg, base / 2.0, 1e-9);
  config.mechanism.lip_shear_modulus_MPa /= 2.0;
  config.mechanism.lip_shear_layer_mm *= 2.0;
  EXPECT_NEAR(release_seedling(config, in).clamp_turn_deg, base * 2.0, 1e-9);
  config.mechanism.lip_shear_layer_mm /= 2.0;
  config.drive.clamp_k_N *= 3.0;
  config.drive.clamp_n = 2.0;
  EXPECT_NEAR(release_seedling(config, in).clamp_turn_deg, base, 1e-12);
  // The stiffness itself: a 245 mm^2 patch on a 10 mm stem, 24.5 mm long.
  const double w = 0.0245, d = 0.010;
  EXPECT_NEAR(lip_turning_stiffness_Nm_per_rad(config.mechanism, 10.0),
              2.0 * 1e6 * w * d * (w * w + d * d) / (12.0 * 0.010), 1e-9);
}

}  // namespace
}  // namespace planter::sim

namespace planter::sim {
namespace {

TEST(SeedlingStrength, IsLognormalWithTheSixMeasuredPeaksMeanAndSd) {
  const config::StrengthFit m = config::measured_strength();
  EXPECT_NEAR(m.mean_N, 161.92, 0.01);  // (181.2 + 191.6 + 162.9 + 137.5 + 127.2 + 171.1) / 6
  EXPECT_NEAR(m.sd_N, 25.1, 0.05);
  EXPECT_DOUBLE_EQ(m.min_N, 127.2);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> z(0.0, 1.0);
  double sum = 0, sq = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = config::lognormal_strength_N(m.mean_N, m.sd_N, z(rng));
    ASSERT_GT(x, 0.0);
    sum += x;
    sq += x * x;
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, m.mean_N, 0.5);
  EXPECT_NEAR(std::sqrt(sq / n - mean * mean), m.sd_N, 0.5);
}

}  // namespace
}  // namespace planter::sim
