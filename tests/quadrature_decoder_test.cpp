#include "firmware/sensing/quadrature_decoder.h"

#include <gtest/gtest.h>

#include "firmware/sensing/ground_speed_estimator.h"

using namespace planter;

namespace {
// Feeds n forward (or backward) x4 steps, one every period_ns.
void turn(QuadratureDecoder& d, int steps, std::int64_t& t, std::int64_t period_ns, int& index) {
  for (int i = 0; i < std::abs(steps); ++i) {
    const int next = (index + (steps > 0 ? 1 : 3)) % 4;
    const bool a = next >= 2, b = next == 1 || next == 2;
    const bool a_changed = (index >= 2) != a;
    t += period_ns;
    d.on_edge({static_cast<std::uint8_t>(a_changed ? 0 : 1), a_changed ? a : b, t});
    index = next;
  }
}
}  // namespace

TEST(QuadratureDecoder, CountsBothDirections) {
  QuadratureDecoder d;
  std::int64_t t = 0;
  int index = 0;
  turn(d, 400, t, 1'000'000, index);
  EXPECT_EQ(d.count(), 400);
  EXPECT_EQ(d.direction(), 1);
  turn(d, -150, t, 1'000'000, index);
  EXPECT_EQ(d.count(), 250);
  EXPECT_EQ(d.direction(), -1);
  EXPECT_EQ(d.invalid_transitions(), 0u);
}

TEST(QuadratureDecoder, RepeatedLevelIsCountedInvalid) {
  QuadratureDecoder d;
  d.on_edge({0, true, 1000});
  d.on_edge({0, true, 2000});  // A rises twice: an edge was lost
  EXPECT_EQ(d.invalid_transitions(), 1u);
}

TEST(QuadratureDecoder, GlitchFilterIgnoresShortPulse) {
  QuadratureDecoder d(20'000);
  std::int64_t t = 0;
  int index = 0;
  turn(d, 4, t, 1'000'000, index);
  ASSERT_EQ(d.count(), 4);
  // A 5 us pulse on A while B is steady.
  d.on_edge({0, true, t + 100'000});
  d.on_edge({0, false, t + 105'000});
  EXPECT_EQ(d.glitches(), 1u);
  EXPECT_LE(std::abs(d.count() - 4), 1);
}

TEST(GroundSpeedEstimator, EdgeTimedSpeed) {
  QuadratureDecoder d;
  const double m_per_count = 0.25e-3;
  GroundSpeedEstimator est(m_per_count, 200'000'000);
  std::int64_t t = 0;
  int index = 0;
  // 0.06 m/s = 240 counts/s: one every 4.1667 ms.
  for (int tick = 0; tick < 100; ++tick) {
    const std::int64_t tick_end = (tick + 1) * 10'000'000LL;
    while (t + 4'166'667 <= tick_end) turn(d, 1, t, 4'166'667, index);
    est.update(d.count(), d.last_count_time_ns(), tick_end);
  }
  EXPECT_NEAR(est.speed_mps(), 0.06, 0.0006);
  EXPECT_NEAR(est.distance_m(), 0.06, 0.001);
  // Stopped: the estimate decays towards zero.
  est.update(d.count(), d.last_count_time_ns(), 10'000'000'000LL);
  EXPECT_LT(est.speed_mps(), 0.001);
}

// The first edge gives no speed (there is no earlier edge to time it from), the second one count
// over the time between them: never one count over the time since boot.
TEST(GroundSpeedEstimator, TheFirstEdgeIsNotTimedFromBoot) {
  QuadratureDecoder d;
  const double m_per_count = 0.92e-3;
  GroundSpeedEstimator est(m_per_count, 200'000'000);
  est.update(d.count(), d.last_count_time_ns(), 3'700'000'000LL);
  EXPECT_EQ(est.speed_mps(), 0.0);
  std::int64_t t = 3'700'000'000LL;
  int index = 0;
  turn(d, 1, t, 100'000'000, index);  // one edge at 3.8 s
  est.update(d.count(), d.last_count_time_ns(), 3'810'000'000LL);
  EXPECT_EQ(est.speed_mps(), 0.0);
  turn(d, 1, t, 80'000'000, index);  // the next 80 ms later: 11.5 mm/s
  est.update(d.count(), d.last_count_time_ns(), 3'890'000'000LL);
  EXPECT_NEAR(est.speed_mps(), m_per_count / 0.08, 1e-6);
}

// After a stop the window does not reach back across it: the second edge after a 5 s stop reads
// one count over the time between the two new edges, not two counts over 5 s.
TEST(GroundSpeedEstimator, TheWindowDoesNotReachAcrossAStop) {
  QuadratureDecoder d;
  const double m_per_count = 0.92e-3;
  GroundSpeedEstimator est(m_per_count, 200'000'000);
  std::int64_t t = 0;
  int index = 0;
  for (int k = 0; k < 50; ++k) {  // 0.092 m/s: an edge every 10 ms
    turn(d, 1, t, 10'000'000, index);
    est.update(d.count(), d.last_count_time_ns(), t);
  }
  EXPECT_NEAR(est.speed_mps(), 0.092, 1e-6);
  turn(d, 1, t, 5'000'000'000LL, index);  // stands 5 s, then one edge
  est.update(d.count(), d.last_count_time_ns(), t);
  turn(d, 1, t, 20'000'000, index);  // the next 20 ms later: 46 mm/s
  est.update(d.count(), d.last_count_time_ns(), t);
  EXPECT_NEAR(est.speed_mps(), m_per_count / 0.02, 1e-6);
}
