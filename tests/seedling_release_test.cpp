// The release mechanics (sim/plant/seedling_release.h): each stage moves the seedling the way
// its force says, and the soil's hold is Broms' with Rankine's coefficient.
#include "sim/plant/seedling_release.h"

#include <gtest/gtest.h>

#include <cmath>

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
  const soil::CohesionlessSoil loam;  // 14 kN/m^3, 30 deg: K_p = 3
  EXPECT_NEAR(soil::passive_coefficient(loam), 3.0, 1e-9);
  const soil::RootAnchorage hold(loam);
  // 0.5 K_p gamma D b^3 for a 10 mm root buried 50 mm.
  EXPECT_NEAR(hold.holding_moment_Nm(0.010, 0.050), 0.5 * 3 * 14000 * 0.010 * 1.25e-4, 1e-12);
  // The same moment through a load 20 mm above the surface: over the lever e + b.
  EXPECT_NEAR(hold.holding_force_N(0.010, 0.050, 0.020),
              hold.holding_moment_Nm(0.010, 0.050) / 0.070, 1e-12);
  EXPECT_NEAR(hold.plowing_force_N(0.010, 0.050), 1.5 * 3 * 14000 * 0.010 * 2.5e-3, 1e-12);
  EXPECT_EQ(hold.holding_moment_Nm(0.010, 0.0), 0.0);
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
  config.mechanism.contact_area_mm2 = 60.0;  // a narrow grip: friction moment mu N w / 4
  in.clamp_force_N = 30.0;
  const double weak = release_seedling(config, in).clamp_turn_deg;
  EXPECT_LT(weak, firm - 2.0) << "firm " << firm << " weak " << weak;
}

}  // namespace
}  // namespace planter::sim
