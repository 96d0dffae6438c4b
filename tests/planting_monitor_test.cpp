// The planting monitor's rules on seedling positions laid out by hand.
#include "firmware/sensing/planting_monitor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace planter;

namespace {
PlantingMonitorConfig monitor_config() {
  PlantingMonitorConfig c;
  c.sensor_fitted = true;
  c.target_spacing_mm = 30.0;
  c.skip_ratio = 1.5;
  c.multiple_ratio = 0.5;
  c.empty_clamps_to_warn = 3;
  return c;
}

// One tick at `distance_m` in which the photo-eye saw seedlings at `at_m`.
void tick(PlantingMonitor& m, double distance_m, const std::vector<double>& at_m,
          bool planting = true) {
  MachineState s;
  s.distance_m = distance_m;
  for (double a : at_m) s.seedling_at_m[s.seedlings_this_tick++] = a;
  m.update(s, planting);
}
}  // namespace

TEST(PlantingMonitor, ClassifiesEachSpacingAgainstTheTarget) {
  PlantingMonitor m(monitor_config());
  // Spacings 30, 46 (skip: over 45), 15 (multiple: at most 15), 44 (single), 30.
  const std::vector<double> at = {0.000, 0.030, 0.076, 0.091, 0.135, 0.165};
  for (double a : at) tick(m, a, {a});
  const PlantingFigures& f = m.figures();
  EXPECT_EQ(f.seedlings, 6.0);
  EXPECT_EQ(f.spacings, 5.0);
  EXPECT_EQ(f.skips, 1.0);
  EXPECT_EQ(f.multiples, 1.0);
  EXPECT_NEAR(f.singulation_pct, 60.0, 1e-9);
  EXPECT_NEAR(f.spacing_mean_mm, 33.0, 1e-9);
  EXPECT_NEAR(f.spacing_mm, 30.0, 1e-9);
  // Population SD of {30, 46, 15, 44, 30}: sqrt((9 + 169 + 324 + 121 + 9) / 5) = sqrt(126.4).
  EXPECT_NEAR(f.spacing_cv, std::sqrt(126.4) / 33.0, 1e-9);
  EXPECT_EQ(f.per_m, 6.0);
}

TEST(PlantingMonitor, SaysNothingOfSpacingBeforeTheSecondSeedling) {
  PlantingMonitor m(monitor_config());
  tick(m, 0.0, {});
  tick(m, 0.010, {0.010});
  EXPECT_EQ(m.figures().seedlings, 1.0);
  EXPECT_EQ(m.figures().spacings, 0.0);
  EXPECT_EQ(m.figures().singulation_pct, 0.0);
}

TEST(PlantingMonitor, AStopWithPlantingOffBreaksTheChain) {
  PlantingMonitor m(monitor_config());
  tick(m, 0.00, {0.00});
  tick(m, 0.03, {0.03});
  tick(m, 0.50, {}, false);  // planting off: the machine moves on with the disc stopped
  tick(m, 0.60, {0.60});     // the first seedling after it: no spacing (not a 570 mm skip)
  tick(m, 0.63, {0.63});
  EXPECT_EQ(m.figures().spacings, 2.0);
  EXPECT_EQ(m.figures().skips, 0.0);
}

TEST(PlantingMonitor, WarnsOfAnEmptyBeltAfterTheConfiguredEmptyClampsAndClearsOnASeedling) {
  PlantingMonitor m(monitor_config());
  tick(m, 0.000, {0.000});
  tick(m, 0.104, {});  // 104 mm: 3.47 pitches, 2 clamps passed empty
  EXPECT_EQ(m.figures().empty_clamps_in_row, 2.0);
  EXPECT_FALSE(m.figures().empty_belt);
  tick(m, 0.106, {});  // 3.53 pitches: the third empty clamp
  EXPECT_EQ(m.figures().empty_clamps_in_row, 3.0);
  EXPECT_TRUE(m.figures().empty_belt);
  tick(m, 0.120, {0.120});
  EXPECT_FALSE(m.figures().empty_belt);
  EXPECT_EQ(m.figures().skips, 1.0);
  tick(m, 0.300, {}, false);  // stopped planting: no warning however far it goes
  EXPECT_FALSE(m.figures().empty_belt);
}

TEST(PlantingMonitor, CountsOnlyTheLastMetreInThePopulation) {
  PlantingMonitor m(monitor_config());
  for (int i = 0; i <= 100; ++i) tick(m, 0.03 * i, {0.03 * i});  // 3 m at 30 mm
  EXPECT_EQ(m.figures().seedlings, 101.0);
  EXPECT_EQ(m.figures().per_m, 34.0);  // 2.01 to 3.00 m
}
