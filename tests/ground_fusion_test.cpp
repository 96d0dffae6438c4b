// The ground fusion (firmware/sensing/ground_fusion.h) against a wheel and a receiver whose
// truth the test knows: the slip it learns, the noise it averages, the fix it drops.
#include "firmware/sensing/ground_fusion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace planter {
namespace {

constexpr std::int64_t kTickNs = 10'000'000;

// A machine at `v` on a row heading east, whose wheel reports 1/k of the ground it rolls; a
// receiver at 10 Hz with `noise` on each axis and 50 ms of latency.
struct Row {
  double v = 0.06, k = 1.05, noise = 0.05;
  double x = 0;
  std::int64_t t = 0;
  std::uint64_t seq = 0;
  std::mt19937_64 rng{7};
  std::normal_distribution<double> n{0, 1};
  hal::GnssFix pending;
  bool has_pending = false;
  bool blocked = false;
  MachineState s;

  void tick() {
    t += kTickNs;
    x += v * 0.01;
    s.distance_m = x / k;
    s.v_wheel_mps = v / k;
    s.gnss_fitted = s.gnss_connected = true;
    if (t % 100'000'000 == 0 && !blocked) {
      const double north = noise * n(rng), east = v + noise * n(rng);
      pending = {};
      pending.sequence = ++seq;
      pending.valid_ns = t;
      pending.mode = hal::GnssMode::k3D;
      pending.satellites = 12;
      pending.hdop = 0.9;
      pending.speed_mps = std::hypot(north, east);
      pending.track_deg = std::atan2(east, north) * 57.29577951308232;
      pending.speed_err_mps = noise;
      has_pending = true;
    }
    if (has_pending && t - pending.valid_ns >= 50'000'000) {
      s.gnss = pending;
      has_pending = false;
    }
  }
};

// The row and the fusion, `ticks` ticks on.
void drive(Row& row, GroundFusion& f, int ticks) {
  for (int i = 0; i < ticks; ++i) {
    row.tick();
    f.update(row.s, row.t);
  }
}

GroundFusionConfig fitted() {
  GroundFusionConfig c;
  c.gnss_fitted = true;
  return c;
}

TEST(GroundFusion, WithoutAReceiverTheDistanceIsTheWheelsExactly) {
  GroundFusion f({});
  MachineState s;
  s.distance_m = 12.345678;
  s.v_wheel_mps = 0.0612;
  f.update(s, kTickNs);
  EXPECT_EQ(f.distance_m(), 12.345678);
  EXPECT_EQ(f.speed_mps(), 0.0612);
  EXPECT_FALSE(f.wheel_alone());
  EXPECT_EQ(f.use(), GnssUse::kNone);
}

TEST(GroundFusion, LearnsAConstantSlipFromAGoodReceiver) {
  GroundFusion f(fitted());
  Row row;
  row.noise = 0.005;
  drive(row, f, 30'000);  // 5 minutes, 18 m
  EXPECT_EQ(f.use(), GnssUse::kUsing);
  EXPECT_NEAR(f.scale_estimate(), 1.05, 2.0 * f.scale_sd()) << "slip " << f.slip();
  EXPECT_LT(f.scale_sd(), 0.02);  // the walk (0.03 per root metre) keeps it from shrinking further
  // What moves the distance: the estimate less one SD toward the calibration.
  EXPECT_NEAR(f.scale(), f.scale_estimate() - f.scale_sd(), 1e-9);
}

// At the paper's 0.06 m/s a consumer receiver's 0.05 m/s is most of the speed: the scale is
// known only as well as its own stated SD, and that SD must be honest.
TEST(GroundFusion, ItsStatedUncertaintyCoversTheTruthWithANoisyReceiver) {
  int within = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    GroundFusion f(fitted());
    Row row;
    row.rng.seed(seed);
    drive(row, f, 30'000);
    within += std::abs(f.scale_estimate() - 1.05) <= 2.0 * f.scale_sd() ? 1 : 0;
  }
  EXPECT_GE(within, 17);  // 95 % within 2 SD, of 20 rows
}

TEST(GroundFusion, ALostFixFallsBackWithinTheTimeoutAndRecovers) {
  GroundFusion f(fitted());
  Row row;
  drive(row, f, 3000);
  ASSERT_EQ(f.use(), GnssUse::kUsing);
  row.blocked = true;
  int ticks_to_fallback = 0;
  while (!f.wheel_alone() && ticks_to_fallback < 1000) {
    row.tick();
    f.update(row.s, row.t);
    ++ticks_to_fallback;
  }
  EXPECT_LE(ticks_to_fallback * 0.01, 0.5 + 0.1 + 0.05);  // timeout, a fix period, latency
  EXPECT_EQ(f.use(), GnssUse::kStale);
  row.blocked = false;
  drive(row, f, 30);
  EXPECT_EQ(f.use(), GnssUse::kUsing);
}

TEST(GroundFusion, RefusesAnImplausibleSpeedAFrozenTimeAndAPoorFix) {
  GroundFusion f(fitted());
  Row row;
  drive(row, f, 1000);
  const double k = f.scale();
  MachineState s = row.s;
  s.gnss.sequence = 1000;
  s.gnss.valid_ns = row.t;
  s.gnss.speed_mps = 1e6;
  f.update(s, row.t + kTickNs);
  EXPECT_EQ(f.scale(), k);
  s.gnss.sequence = 1001;
  s.gnss.speed_mps = 0.06;
  s.gnss.valid_ns = row.s.gnss.valid_ns;  // the time stood still
  f.update(s, row.t + 2 * kTickNs);
  EXPECT_EQ(f.scale(), k);
  s.gnss.sequence = 1002;
  s.gnss.valid_ns = row.t + 2 * kTickNs;
  s.gnss.hdop = 12;
  f.update(s, row.t + 3 * kTickNs);
  EXPECT_EQ(f.scale(), k);
  s.gnss.sequence = 1003;
  s.gnss.hdop = 0.9;
  s.gnss.speed_mps = std::nan("");
  f.update(s, row.t + 4 * kTickNs);
  EXPECT_EQ(f.scale(), k);
}

TEST(GroundFusion, AReceiverThatDisconnectsIsTheWheelAlone) {
  GroundFusion f(fitted());
  Row row;
  drive(row, f, 1000);
  row.s.gnss_connected = false;
  f.update(row.s, row.t + kTickNs);
  EXPECT_TRUE(f.wheel_alone());
  EXPECT_EQ(f.use(), GnssUse::kDisconnected);
}

}  // namespace
}  // namespace planter
