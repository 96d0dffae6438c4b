#include <gtest/gtest.h>

#include <cmath>

#include "firmware/control/clamp_force_loop.h"
#include "firmware/control/furrow_depth_loop.h"
#include "firmware/control/sigma_loop.h"

using namespace planter;

TEST(SigmaLoop, FollowsDistanceNotTime) {
  SigmaLoopConfig cfg;
  SigmaLoop loop(cfg);
  loop.engage(1.0, 2.0);
  // Steady: the feed-forward alone is sigma * v / R.
  EXPECT_NEAR(loop.update(1.0, 0.06, 2.0), 1.5 * 0.06 / 0.3, 1e-12);
  // The machine stopped after 0.1 m more; the disc lags 0.01 rad: a correction, no feed-forward.
  const double cmd = loop.update(1.1, 0.0, 2.0 + 1.5 * 0.1 / 0.3 - 0.01);
  EXPECT_NEAR(cmd, cfg.angle_gain_per_s * 0.01, 1e-9);
  // Ahead of the reference: the disc waits rather than running backwards.
  EXPECT_EQ(loop.update(1.1, 0.0, 3.0), 0.0);
  EXPECT_LE(loop.update(100.0, 5.0, 0.0), cfg.omega_max_radps);
}

TEST(ClampForceLoop, NeverCommandsPastTheCeiling) {
  ClampLoopConfig cfg;
  ClampForceLoop loop(cfg);
  // A load cell that reads far too low (broken wire): the PI would wind up without limit.
  double cmd = 0;
  for (int i = 0; i < 10000; ++i) cmd = loop.update(0.0, 0.01, true);
  EXPECT_LE(cmd, loop.model_position_mm(0.97 * cfg.ceiling_N) + loop.trim_mm() + 1e-9);
  // The model position for the ceiling, with the trim the integrator could reach, stays bounded.
  EXPECT_LE(cmd, cfg.position_max_mm);
  // Anti-windup: once the reading is right the loop comes off the limit within a few steps.
  const double x90 = loop.model_position_mm(90.0);
  for (int i = 0; i < 300; ++i)
    cmd = loop.update(cfg.model_k_N * std::pow(std::max(0.0, cmd - cfg.model_x0_mm), cfg.model_n),
                      0.01, true);
  EXPECT_NEAR(cmd, x90, 0.2);
}

TEST(ClampForceLoop, BacksOffAboveCeiling) {
  ClampLoopConfig cfg;
  ClampForceLoop loop(cfg);
  for (int i = 0; i < 500; ++i) loop.update(90.0, 0.01, true);
  const double before = loop.update(90.0, 0.01, true);
  const double after = loop.update(125.0, 0.01, true);
  EXPECT_TRUE(loop.ceiling_active());
  EXPECT_LT(after, before - 0.1);
}

TEST(ClampForceLoop, ReleasesWhenDisabled) {
  ClampLoopConfig cfg;
  ClampForceLoop loop(cfg);
  loop.update(50.0, 0.01, true);
  EXPECT_EQ(loop.update(50.0, 0.01, false), cfg.release_position_mm);
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
