// Every named alarm (warning:: bits, firmware/supervisor/loop_alarms.h) raised by its condition
// and cleared after it, and the load cell's zero.
#include "firmware/supervisor/loop_alarms.h"

#include <gtest/gtest.h>

#include "firmware/sensing/load_cell_zero.h"
#include "firmware/supervisor/supervisor.h"

using namespace planter;

namespace {

LoopAlarmInputs gripping() {
  LoopAlarmInputs in;
  in.running = true;
  in.clamp_setpoint_N = 90.0;
  in.clamp.clamping = true;
  in.clamp.ramped = true;
  in.clamp.measured_N = 90.0;
  in.clamp.model_force_N = 90.0;
  in.depth.settled = true;
  return in;
}

// Ticks `in` for `seconds`; returns the warnings of the last tick.
std::uint32_t hold(LoopAlarms& a, const LoopAlarmInputs& in, double seconds) {
  std::uint32_t w = 0;
  for (int i = 0; i < static_cast<int>(seconds / in.dt_s + 0.5); ++i) w = a.update(in);
  return w;
}

struct Case {
  const char* name;
  std::uint32_t bit;
  void (*disturb)(LoopAlarmInputs&);
};

const Case kCases[] = {
    {"too fast", warning::kTooFastForDisc, [](LoopAlarmInputs& in) { in.sigma.too_fast = true; }},
    {"lagging", warning::kDiscLagging, [](LoopAlarmInputs& in) { in.sigma.lag_held = true; }},
    {"short", warning::kClampShort,
     [](LoopAlarmInputs& in) {
       in.clamp.at_travel = true;
       in.clamp.measured_N = 60.0;
       in.clamp.model_force_N = 60.0;
     }},
    {"disagrees", warning::kLoadCellDisagrees,
     [](LoopAlarmInputs& in) { in.clamp.model_force_N = 115.0; }},
    {"ceiling", warning::kClampAtCeiling, [](LoopAlarmInputs& in) { in.clamp.ceiling = true; }},
    {"end stop", warning::kDepthUnreachable,
     [](LoopAlarmInputs& in) {
       in.depth.at_end_stop = true;
       in.depth.error_mm = 6.0;
     }},
    {"depth off", warning::kDepthOffBand, [](LoopAlarmInputs& in) { in.depth.error_mm = -3.0; }},
};

}  // namespace

// A stem giving way is said the tick it is seen, held for the operator's glance.
TEST(LoopAlarms, AStemGivingWayIsSaidAtOnce) {
  const LoopAlarmConfig cfg;
  LoopAlarms a{cfg};
  LoopAlarmInputs in = gripping();
  in.clamp.stem_gave_way = true;
  EXPECT_EQ(a.update(in), warning::kStemGaveWay);
  EXPECT_EQ(hold(a, gripping(), cfg.hold_s - 0.1), warning::kStemGaveWay);
  EXPECT_EQ(hold(a, gripping(), 0.2), 0u);
}

TEST(LoopAlarms, NominalRaisesNothing) {
  LoopAlarms a{LoopAlarmConfig{}};
  EXPECT_EQ(hold(a, gripping(), 10.0), 0u);
}

TEST(LoopAlarms, EachAlarmRisesWithinASecondAndClearsAfterItsHold) {
  const LoopAlarmConfig cfg;
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.name);
    LoopAlarms a{cfg};
    LoopAlarmInputs in = gripping();
    c.disturb(in);
    EXPECT_EQ(hold(a, in, 0.05), 0u) << "raised on a blip";
    EXPECT_EQ(hold(a, in, 0.95), c.bit) << "not raised, or another with it, within 1 s";
    // Cleared: still shown for hold_s, then gone.
    EXPECT_EQ(hold(a, gripping(), cfg.hold_s - 0.1), c.bit);
    EXPECT_EQ(hold(a, gripping(), 0.2), 0u);
  }
}

TEST(LoopAlarms, NotRunningRaisesNoLoopAlarm) {
  for (const Case& c : kCases) {
    LoopAlarms a{LoopAlarmConfig{}};
    LoopAlarmInputs in = gripping();
    c.disturb(in);
    in.running = false;
    EXPECT_EQ(hold(a, in, 3.0), 0u) << c.name;
  }
}

TEST(LoopAlarms, EmptyClampsAfterAWeakGripAreSeedlingsFallingElseAnEmptyBelt) {
  const LoopAlarmConfig cfg;
  LoopAlarms a{cfg};
  LoopAlarmInputs in = gripping();
  in.empty_belt = true;
  // A good grip all along: the belt is empty.
  EXPECT_EQ(a.update(in), warning::kEmptyBelt);
  // The grip went weak at this disc angle: the empty clamps that follow within a carry are
  // seedlings that fell out.
  in.empty_belt = false;
  in.clamp.measured_N = 30.0;
  a.update(in);
  in.clamp.measured_N = 90.0;
  in.disc_angle_rad += 2.0;
  in.empty_belt = true;
  EXPECT_EQ(a.update(in), warning::kSeedlingsFalling);
  // Clamps empty far past a carry from the weak grip: the belt again.
  in.disc_angle_rad += cfg.carry_rad + 10.0 * cfg.clamp_pitch_rad;
  EXPECT_EQ(a.update(in), warning::kEmptyBelt);
  in.empty_belt = false;
  EXPECT_EQ(a.update(in), 0u);
}

TEST(LoopAlarms, ALoadCellDriftingAwayFromTheRollerIsSaidBeforeTheFastThreshold) {
  const LoopAlarmConfig cfg;
  LoopAlarms a{cfg};
  LoopAlarmInputs in = gripping();
  // Settled with a standing disagreement of +2 N (the stems' share of the force).
  in.clamp.measured_N = 92.0;
  EXPECT_EQ(hold(a, in, cfg.drift_settle_s + 5.0), 0u);
  // Then the cell drifts down 2 N a minute: said once the slow mean has moved drift_N, while
  // the fast threshold (10 % + 4 N) is still far off.
  std::uint32_t w = 0;
  double t = 0;
  while (w == 0 && t < 300.0) {
    in.clamp.measured_N = 92.0 - 2.0 / 60.0 * t;
    w = a.update(in);
    t += in.dt_s;
  }
  EXPECT_EQ(w, warning::kLoadCellDisagrees);
  const double drift_N = 2.0 / 60.0 * t;
  EXPECT_GT(drift_N, cfg.drift_N);
  EXPECT_LT(drift_N, cfg.drift_N + 1.0);  // the slow mean's lag: tau x rate = 0.33 N
  EXPECT_LT(drift_N + 2.0, cfg.disagree_share * 90.0 + cfg.disagree_offset_N);
}

TEST(LoopAlarms, EveryBitHasAName) {
  for (int bit = 0; bit < warning::kCount; ++bit) EXPECT_STRNE(warning::name(bit), "") << bit;
  EXPECT_STREQ(warning::name(warning::kCount), "");
  const std::uint32_t all = (1u << warning::kCount) - 1u;
  EXPECT_EQ((warning::kSigmaAlarms | warning::kClampAlarms | warning::kDepthAlarms |
             warning::kEmptyBelt) &
                ~all,
            0u);
}

TEST(LoadCellZero, TheOpenLipsMeanIsTheZeroAndABigOffsetIsNotHidden) {
  LoadCellZero z{LoadCellZeroConfig{}};
  for (int i = 0; i < 30; ++i) z.update(-5.0 + (i % 2 ? 0.5 : -0.5), true);
  EXPECT_NEAR(z.offset_N(), -5.0, 1e-9);
  EXPECT_NEAR(z.corrected_N(85.0), 90.0, 1e-9);
  // Closed: the zero is kept.
  z.update(90.0, false);
  EXPECT_NEAR(z.offset_N(), -5.0, 1e-9);
  // A new open stretch starts a new mean; a 40 N offset is bounded to what may be taken.
  for (int i = 0; i < 30; ++i) z.update(40.0, true);
  EXPECT_EQ(z.offset_N(), z.config().max_offset_N);
}
