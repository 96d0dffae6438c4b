#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "firmware/control/clamp_force_loop.h"
#include "firmware/control/furrow_depth_loop.h"
#include "firmware/control/sigma_loop.h"

using namespace planter;

TEST(SigmaLoop, FollowsDistanceNotTime) {
  SigmaLoopConfig cfg;
  SigmaLoop loop(cfg);
  loop.engage(1.0, 2.0);
  // Steady: the feed-forward alone is sigma * v / R.
  EXPECT_NEAR(loop.update(1.0, 0.06, 2.0, 0.01), 1.5 * 0.06 / 0.3, 1e-12);
  // The machine stopped after 0.1 m more; the disc lags 0.01 rad: a correction, no feed-forward.
  const double cmd = loop.update(1.1, 0.0, 2.0 + 1.5 * 0.1 / 0.3 - 0.01, 0.01);
  EXPECT_NEAR(cmd, cfg.angle_gain_per_s * 0.01, 1e-9);
  // Ahead of the reference: the disc waits rather than running backwards.
  EXPECT_EQ(loop.update(1.1, 0.0, 3.0, 0.01), 0.0);
  EXPECT_LE(loop.update(100.0, 5.0, 0.0, 0.01), cfg.omega_max_radps);
}

TEST(SigmaLoop, ADiscThatCannotKeepUpDoesNotRaceAfterwards) {
  SigmaLoopConfig cfg;
  SigmaLoop loop(cfg);
  loop.engage(0.0, 0.0);
  // 0.30 m/s for 60 s with the disc at its top speed: the reference would run 30 rad ahead.
  double angle = 0, distance = 0;
  for (int i = 0; i < 6000; ++i) {
    distance += 0.30 * 0.01;
    angle += loop.update(distance, 0.30, angle, 0.01) * 0.01;
    EXPECT_LE(loop.angle_error_rad(), cfg.max_lag_rad() + 1e-12);
  }
  EXPECT_TRUE(loop.status().too_fast);
  // The machine slows to 0.06 m/s: the disc goes back to sigma v / R within a few seconds,
  // not at its top speed for the 12 m it had fallen behind.
  double cmd = 0;
  for (int i = 0; i < 500; ++i) {
    distance += 0.06 * 0.01;
    cmd = loop.update(distance, 0.06, angle, 0.01);
    angle += cmd * 0.01;
  }
  EXPECT_FALSE(loop.status().too_fast);
  EXPECT_NEAR(cmd, 1.5 * 0.06 / 0.3, 0.02);
}

TEST(SigmaLoop, IntegralWhenOnTakesADraggingDrivesLagDownToItsDeadBand) {
  SigmaLoopConfig cfg;
  cfg.angle_integral_per_s2 = 0.6;  // off by default (sigma_loop.h says why)
  SigmaLoop loop(cfg);
  loop.engage(0.0, 0.0);
  // A drive that turns 0.05 rad/s slower than commanded (friction): P alone would leave a
  // steady lag of 0.05 / 3 rad; the integral takes it down to its dead band.
  double angle = 0, distance = 0;
  for (int i = 0; i < 6000; ++i) {
    distance += 0.06 * 0.01;
    angle += std::max(0.0, loop.update(distance, 0.06, angle, 0.01) - 0.05) * 0.01;
  }
  EXPECT_LT(std::abs(loop.angle_error_rad()), cfg.integral_dead_band_rad + 0.001);
  EXPECT_GT(0.05 / cfg.angle_gain_per_s, cfg.integral_dead_band_rad + 0.005);
}

// The rim's speed at the paper's 0.278 rad/s on its 0.3 m disc.
constexpr double kRimMmPerS = 83.4;

TEST(ClampForceLoop, NeverCommandsPastTheCeiling) {
  ClampLoopConfig cfg;
  ClampForceLoop loop(cfg);
  // A load cell that reads far too low (broken wire): the PI would wind up without limit.
  double cmd = 0;
  for (int i = 0; i < 10000; ++i) cmd = loop.update(0.0, cmd, kRimMmPerS, 0.01, true);
  // The second path: the roller never past where the law gives the ceiling's guard.
  EXPECT_LE(cmd, loop.model_position_mm(0.97 * cfg.ceiling_N) + 1e-9);
  EXPECT_LE(cmd, cfg.position_max_mm);
  // Anti-windup: once the reading is right the loop comes off the limit within a few steps.
  const double x90 = loop.model_position_mm(90.0);
  for (int i = 0; i < 300; ++i)
    cmd = loop.update(loop.model_force_N(cmd), cmd, kRimMmPerS, 0.01, true);
  EXPECT_NEAR(cmd, x90, 0.2);
}

TEST(ClampForceLoop, StifferLipsDoNotLatchTheClampOpen) {
  // Lips twice as stiff as the loop's law: the force overshoots, the loop backs off, and
  // must then settle at the set-point (the old loop sat at 0 N for 32 s).
  ClampLoopConfig cfg;
  ClampForceLoop loop(cfg);
  const auto lips_N = [&](double x) { return 2.0 * loop.model_force_N(x); };
  double cmd = 0, roller = 0;
  for (int i = 0; i < 1000; ++i) {
    roller += (cmd - roller) * 0.2;  // the roller's 0.05 s lag at 10 ms
    cmd = loop.update(lips_N(roller), roller, kRimMmPerS, 0.01, true);
  }
  EXPECT_NEAR(lips_N(roller), 90.0, 2.0);
}

// A stem coming under the roller adds compression the law does not hold, over the rim's
// entry_mm. The loop reads it each tick and takes it into the feed-forward: the force holds
// near its set-point, and the stem's diameter is read from what it adds.
namespace {
struct NipBench {
  ClampForceLoop& loop;
  double cmd = 0, roller = 0, added_mm = 0, worst_N = 0;
  double force() const { return loop.model_force_N(roller + added_mm); }
  void tick() {
    roller += (cmd - roller) * 0.2;  // the roller's 0.05 s lag at 10 ms
    cmd = loop.update(force(), roller, kRimMmPerS, 0.01, true);
  }
  // The stem comes in over entry_mm at the rim's speed, then stays `hold` ticks.
  void stem_in(double stem_mm, int hold) {
    const double ticks = loop.stem().config().entry_mm / kRimMmPerS / 0.01;
    for (int i = 1; i <= static_cast<int>(ticks) + hold; ++i) {
      added_mm = stem_mm * std::min(1.0, i / ticks);
      tick();
      worst_N = std::max(worst_N, force());
    }
  }
};
}  // namespace

TEST(ClampForceLoop, AStemComingInIsReadAndItsForceHeld) {
  ClampLoopConfig cfg;
  cfg.per_stem_grip = false;
  ClampForceLoop loop(cfg);
  NipBench nip{loop};
  for (int i = 0; i < 3000; ++i) nip.tick();  // settled on the empty nip
  nip.stem_in(0.8, 30);  // a 11.6 mm stem: 0.8 mm more, about 25 N at the same position
  EXPECT_NEAR(loop.stem().diameter_mm(kRimMmPerS), 11.6, 0.2);
  EXPECT_LT(nip.worst_N, 90.0 + 9.0);  // within the goal's band while it comes in
  EXPECT_NEAR(nip.force(), 90.0, 2.0);
}

TEST(ClampForceLoop, AThickStemIsGrippedUnderItsOwnCeiling) {
  for (const bool per_stem : {true, false}) {
    ClampLoopConfig cfg;
    cfg.per_stem_grip = per_stem;
    ClampForceLoop loop(cfg);
    NipBench nip{loop};
    for (int i = 0; i < 3000; ++i) nip.tick();
    nip.stem_in(2.0, 60);  // 14 mm: its ceiling 120 x 10 / 14 = 85.7 N, aimed 5 % below
    // The baseline (5 s) has taken 0.2 mm of the stem in its 0.7 s: read as 13.6 mm, 83.8 N.
    const double expected_N = per_stem ? 0.95 * cfg.ceiling_N * 10.0 / 13.6 : cfg.setpoint_N;
    EXPECT_NEAR(nip.force(), expected_N, 2.5) << (per_stem ? "per stem" : "one set-point");
  }
}

TEST(ClampForceLoop, TheLoadCellsNoiseIsNoCollapse) {
  ClampLoopConfig cfg;
  ClampForceLoop loop(cfg);
  double cmd = 0, roller = 0;
  std::uint32_t seed = 12345;
  for (int i = 0; i < 20000; ++i) {
    seed = seed * 1664525u + 1013904223u;  // +-1.7 N uniform: 1 N RMS
    const double noise = (static_cast<double>(seed >> 8) / 16777216.0 - 0.5) * 3.46;
    roller += (cmd - roller) * 0.2;
    cmd = loop.update(loop.model_force_N(roller) + noise, roller, kRimMmPerS, 0.01, true);
  }
  EXPECT_EQ(loop.stem().collapses(), 0);
  EXPECT_NEAR(loop.stem().diameter_mm(kRimMmPerS), 10.0, 0.3);
}

// A wall that gives way opens the nip by about a millimetre at once: seen, said, and every
// stem's ceiling lowered a little, coming back slowly.
TEST(ClampForceLoop, ACollapseIsSeenSaidAndLearnedFrom) {
  ClampLoopConfig cfg;
  ClampForceLoop loop(cfg);
  NipBench nip{loop};
  for (int i = 0; i < 3000; ++i) nip.tick();
  nip.stem_in(1.0, 20);
  EXPECT_EQ(loop.stem().collapses(), 0);
  nip.added_mm -= 1.2;  // the wall gives way
  nip.tick();
  EXPECT_TRUE(loop.status().stem_gave_way);
  nip.tick();
  EXPECT_FALSE(loop.status().stem_gave_way);
  EXPECT_EQ(loop.stem().collapses(), 1);
  EXPECT_NEAR(loop.ceiling_share(), 1.0 - cfg.collapse_backoff, 1e-3);
  for (int i = 0; i < 1000; ++i) nip.tick();  // 10 s: back by 1 %
  EXPECT_NEAR(loop.ceiling_share(), 1.0 - cfg.collapse_backoff + 10 * cfg.backoff_recovery_per_s,
              1e-3);
  EXPECT_EQ(loop.stem().collapses(), 1);  // the force's recovery is no second collapse
}

TEST(ClampForceLoop, ALoadCellReadingLowCannotPushPastTheCeiling) {
  ClampLoopConfig cfg;
  ClampForceLoop loop(cfg);
  double cmd = 0, roller = 0;
  for (int i = 0; i < 3000; ++i) {
    roller += (cmd - roller) * 0.2;
    cmd = loop.update(0.6 * loop.model_force_N(roller) - 10.0, roller, kRimMmPerS, 0.01, true);
  }
  EXPECT_LE(loop.model_force_N(roller), 0.97 * cfg.ceiling_N + 1e-6);
  EXPECT_TRUE(loop.status().at_travel);
}

TEST(ClampForceLoop, BacksOffAboveCeiling) {
  ClampLoopConfig cfg;
  ClampForceLoop loop(cfg);
  double roller = 0;
  for (int i = 0; i < 500; ++i) roller = loop.update(90.0, roller, kRimMmPerS, 0.01, true);
  const double before = loop.update(90.0, roller, kRimMmPerS, 0.01, true);
  const double after = loop.update(125.0, before, kRimMmPerS, 0.01, true);
  EXPECT_TRUE(loop.ceiling_active());
  EXPECT_LT(after, before - 0.1);
}

TEST(ClampForceLoop, ReleasesWhenDisabled) {
  ClampLoopConfig cfg;
  ClampForceLoop loop(cfg);
  loop.update(50.0, 4.0, kRimMmPerS, 0.01, true);
  EXPECT_EQ(loop.update(50.0, 4.0, kRimMmPerS, 0.01, false), cfg.release_position_mm);
}

TEST(FurrowDepthLoop, RateLimitedRampAndTrim) {
  DepthLoopConfig cfg;
  FurrowDepthLoop loop(cfg);
  loop.reset(0.0);
  double cmd = loop.update(0.0, 0.01, true);
  EXPECT_NEAR(cmd, cfg.rate_mm_per_s * 0.01, 1e-9);
  // Ramp to the target, then a constant 3 mm sag is trimmed out.
  double depth = 0;
  for (int i = 0; i < 3000; ++i) {
    cmd = loop.update(depth, 0.01, true);
    depth = cmd - 3.0;
  }
  EXPECT_NEAR(depth, cfg.target_mm, 0.05);
}

TEST(FurrowDepthLoop, TheTrimReachesTheEndStopAndSaysSo) {
  DepthLoopConfig cfg;
  FurrowDepthLoop loop(cfg);
  loop.reset(0.0);
  // A sag of 25 mm (hard soil): more than the old 15 mm cap, within the travel.
  double depth = 0, cmd = 0;
  for (int i = 0; i < 6000; ++i) {
    cmd = loop.update(depth, 0.01, true);
    depth = cmd - 25.0;
  }
  EXPECT_NEAR(depth, cfg.target_mm, 0.05);
  EXPECT_FALSE(loop.status().at_end_stop);
  // A target 5 mm short of the end stop with 25 mm of sag: held at the stop, and said.
  loop.set_target_mm(cfg.max_mm - 5.0);
  for (int i = 0; i < 6000; ++i) {
    cmd = loop.update(depth, 0.01, true);
    depth = cmd - 25.0;
  }
  EXPECT_EQ(cmd, cfg.max_mm);
  EXPECT_TRUE(loop.status().at_end_stop);
  EXPECT_NEAR(loop.status().error_mm, 20.0, 0.05);
}
