#pragma once
// One ground distance and speed from the soil wheel and, where fitted, a GNSS receiver. The
// wheel is precise over a seedling's spacing but its scale drifts with slip; GNSS speed is
// unbiased but noisy and late. A Kalman filter with one state, the ground's metres per metre
// the wheel reports (its scale k, 1 / (1 - slip) against the calibration), the form of the
// wheel-odometry scale-factor filters (Groves, Principles of GNSS, Inertial, and Multisensor
// Integrated Navigation Systems, 2nd ed., 2013, Sec. 16.3): k walks along the row (slip
// changes with the soil, not with time), and each usable fix's speed along the row measures
// k times the wheel's speed over the same interval, taken from a history of the wheel so the
// receiver's latency does not bias it. The distance is the wheel's times k, so between fixes
// and after the fix is lost it is the wheel's own, at the scale last learned.
//
// Speed along the row, not speed over ground: the receiver's speed is the length of a noisy
// velocity, biased up when the noise is near the speed (a Rice distribution; at the paper's
// 0.06 m/s and 0.05 m/s of noise it reads about half again too fast). Its component along the
// row's heading, learned from the mean velocity, is unbiased.
#include <array>
#include <cstdint>

#include "firmware/io/process_image.h"
#include "firmware/sensing/gnss_use.h"
#include "firmware/supervisor/supervisor.h"

namespace planter {

struct GroundFusionConfig {
  bool gnss_fitted = false;  // the board names a receiver
  // A fix is used while all of these hold (assumed: the usual limits of receivers' own
  // "good fix" flags; a 2D fix gives speed as well as a 3D one).
  int min_satellites = 5;
  double max_hdop = 4.0;
  double max_speed_err_mps = 0.5;
  // The speed error when the receiver states none (a consumer datasheet's 0.05 m/s, 1 sigma).
  double default_speed_err_mps = 0.05;
  // No usable fix for this long: the wheel alone, and the alarm (half the operator's second).
  double fix_timeout_s = 0.5;
  // How far k may walk per metre of row, 1 sigma, and how far it may be from the calibration
  // at the start (assumed). These two and apply_beyond_sd below are the three values tuned,
  // on the disturbance suite's named cases (walk 0.002-0.05, start 0.03-0.05, threshold 0-2
  // SD): the nominal case's sigma error 0.76 -> 0.81 % against 1.92 % with no threshold.
  double scale_walk_per_sqrt_m = 0.03;
  double scale_start_sd = 0.05;
  // The estimate moves the distance only by what it holds beyond this many of its own SD from
  // the calibration (a soft threshold, Donoho and Johnstone, Biometrika 81(3), 1994): a
  // receiver too noisy to tell the slip from the calibration leaves the wheel's distance as
  // it is, rather than adding its noise to it.
  double apply_beyond_sd = 1.0;
  // A speed further than this many sigma from the wheel's times k is refused (a jump).
  double gate_sigma = 5.0;
  // Above this a speed is implausible: the supervisor's limit, declared there.
  double max_speed_mps = SupervisorConfig{}.ground_speed_plausible_max_mps;
};

class GroundFusion {
 public:
  explicit GroundFusion(const GroundFusionConfig& config);

  // Once per tick, after the I/O layer's read.
  void update(const MachineState& in, std::int64_t now_ns);

  // Ground distance on the fused scale, for a distance the wheel reported this tick or
  // shortly before (a seedling's).
  [[nodiscard]] double ground_m(double wheel_m) const {
    return anchor_ground_m_ + k_ * (wheel_m - anchor_wheel_m_);
  }
  [[nodiscard]] double distance_m() const { return distance_m_; }
  [[nodiscard]] double speed_mps() const { return speed_mps_; }
  // The wheel's slip beyond its calibration, 1 - 1/k.
  [[nodiscard]] double slip() const { return 1.0 - 1.0 / k_est_; }
  [[nodiscard]] double scale() const { return k_; }
  // The estimate itself, before the threshold, and its SD.
  [[nodiscard]] double scale_estimate() const { return k_est_; }
  [[nodiscard]] double scale_sd() const;
  [[nodiscard]] GnssUse use() const { return use_; }
  // The receiver is fitted and its speed is not being used now.
  [[nodiscard]] bool wheel_alone() const { return cfg_.gnss_fitted && use_ != GnssUse::kUsing; }
  [[nodiscard]] double along_row_mps() const { return along_row_mps_; }
  [[nodiscard]] std::uint64_t fixes_used() const { return used_; }
  [[nodiscard]] std::uint64_t fixes_refused() const { return refused_; }

 private:
  struct WheelSample {
    std::int64_t t_ns;
    double wheel_m;
  };
  void remember(std::int64_t now_ns, double wheel_m);
  [[nodiscard]] bool wheel_at(std::int64_t t_ns, double& wheel_m) const;
  void take(const hal::GnssFix& fix);
  void set_estimate(double k, double wheel_now_m);

  GroundFusionConfig cfg_;
  double k_ = 1.0;      // applied to the wheel's distance
  double k_est_ = 1.0;  // the filter's estimate, and its variance
  double p_ = 0.0;
  double anchor_ground_m_ = 0.0, anchor_wheel_m_ = 0.0;
  double last_wheel_m_ = 0.0;
  double distance_m_ = 0.0, speed_mps_ = 0.0, along_row_mps_ = 0.0;
  // The row's heading from the mean velocity (north and east sums, m/s).
  double sum_north_ = 0.0, sum_east_ = 0.0;
  GnssUse use_ = GnssUse::kNone;
  std::uint64_t last_seq_ = 0;
  std::int64_t last_fix_ns_ = 0;     // the last fix taken, its time of validity
  std::int64_t last_usable_ns_ = 0;  // when the last usable fix arrived (controller's clock)
  bool ever_usable_ = false;
  std::uint64_t used_ = 0, refused_ = 0;
  static constexpr std::size_t kHistory = 512;  // 5 s of 10 ms ticks: latencies up to a second
  std::array<WheelSample, kHistory> history_{};
  std::size_t head_ = 0, filled_ = 0;
};

// Whether a fix is good enough to use by itself (mode, figures, quality, a time that moves on
// from `last_fix_ns`, the last fix taken; 0: none): kUsing, or why not.
GnssUse judge_fix(const GroundFusionConfig& config, const hal::GnssFix& fix,
                  std::int64_t last_fix_ns);

}  // namespace planter
