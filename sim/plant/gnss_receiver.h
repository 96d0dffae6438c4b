#pragma once
// The GNSS receiver as the controller meets it: a fix every 1/rate_hz, its velocity the true
// one plus white noise on each horizontal axis (a receiver's Doppler velocity, Kaplan and
// Hegarty, Understanding GPS/GNSS, 3rd ed., 2017, Sec. 11.4), delivered latency_s after it
// was valid, and none while the sky is blocked. Speed over ground and track are what receivers
// report (NMEA RMC, gpsd's TPV), so the speed is the noisy velocity's length.
#include <cmath>
#include <cstdint>
#include <deque>
#include <random>

#include "config/local_plane.h"
#include "hal/sim/sim_gnss.h"
#include "sim/plant/plant_config.h"

namespace planter::sim {

class GnssReceiverModel {
 public:
  GnssReceiverModel(const GnssConfig& config, std::uint64_t seed)
      : cfg_(config), rng_(seed ^ 0x6e55'0000'0000'0001ull) {}

  // Once a plant step: a fix measured at each epoch in the step, each handed on once late.
  void step(std::int64_t t_ns, double x_m, double v_mps, hal::sim::SimGnss& out) {
    const auto period_ns = static_cast<std::int64_t>(1e9 / cfg_.rate_hz);
    while (next_ns_ <= t_ns) {
      measure(next_ns_, x_m, v_mps);
      next_ns_ += period_ns;
    }
    const auto latency_ns = static_cast<std::int64_t>(cfg_.latency_s * 1e9);
    while (!pending_.empty() && pending_.front().valid_ns + latency_ns <= t_ns) {
      out.put(pending_.front());
      pending_.pop_front();
    }
  }
  // Whether the sky is blocked at x (the scenario's dropout).
  [[nodiscard]] bool blocked(double x_m, std::int64_t t_ns) {
    if (cfg_.dropout_at_m < 0 || x_m < cfg_.dropout_at_m) return false;
    if (blocked_from_ns_ < 0) blocked_from_ns_ = t_ns;
    return static_cast<double>(t_ns - blocked_from_ns_) * 1e-9 < cfg_.dropout_s;
  }

 private:
  void measure(std::int64_t t_ns, double x_m, double v_mps) {
    constexpr double kDeg = config::LocalPlane::kDeg;
    hal::GnssFix f;
    f.sequence = ++sequence_;
    f.valid_ns = t_ns;
    if (blocked(x_m, t_ns)) {
      f.mode = hal::GnssMode::kNoFix;
      pending_.push_back(f);
      return;
    }
    const double h = cfg_.heading_deg * kDeg;
    const double north = v_mps * std::cos(h) + cfg_.speed_noise_mps * normal_(rng_);
    const double east = v_mps * std::sin(h) + cfg_.speed_noise_mps * normal_(rng_);
    f.mode = hal::GnssMode::k3D;
    f.satellites = cfg_.satellites;
    f.hdop = cfg_.hdop;
    f.speed_mps = std::hypot(north, east);
    f.track_deg = std::fmod(std::atan2(east, north) / kDeg + 360.0, 360.0);
    f.speed_err_mps = cfg_.speed_noise_mps;
    const double pn = x_m * std::cos(h) + cfg_.position_noise_m * normal_(rng_);
    const double pe = x_m * std::sin(h) + cfg_.position_noise_m * normal_(rng_);
    config::LocalPlane{cfg_.origin_lat_deg, cfg_.origin_lon_deg}.to_geo(pe, pn, f.lat_deg,
                                                                        f.lon_deg);
    pending_.push_back(f);
  }

  GnssConfig cfg_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  std::deque<hal::GnssFix> pending_;
  std::int64_t next_ns_ = 0;
  std::uint64_t sequence_ = 0;
  std::int64_t blocked_from_ns_ = -1;
};

}  // namespace planter::sim
