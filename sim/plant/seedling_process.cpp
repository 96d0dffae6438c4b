#include "sim/plant/seedling_process.h"

#include <algorithm>
#include <cmath>

namespace planter::sim {
namespace {
constexpr double kDegPerRad = 57.29577951308232;
}

SeedlingProcess::SeedlingProcess(const PlantConfig& config, std::uint64_t seed)
    : cfg_(config), rng_(seed) {
  seedlings_.reserve(2048);
}

double SeedlingProcess::contact_area_factor() const {
  return sim::contact_area_factor(cfg_.mechanism.contact_area_mm2);
}

double SeedlingProcess::nip_thickness_mm(double t_s) const {
  if (seedlings_.empty()) return 0.0;
  const Seedling& s = seedlings_.back();
  if (t_s - s.pickup_time_s > cfg_.mechanism.nip_time_s) return 0.0;
  return std::max(0.0, (s.diameter_mm - cfg_.seedlings.reference_diameter_mm) *
                           cfg_.drive.seedling_thickness_gain);
}

void SeedlingProcess::step(double disc_angle_rad, double clamp_force_N,
                           const ReleaseConditions& now, double vibration_tilt_deg) {
  const SeedlingConfig& sc = cfg_.seedlings;
  const MechanismConfig& mc = cfg_.mechanism;
  if (!started_) {
    next_pickup_angle_rad_ = disc_angle_rad;
    started_ = true;
  }
  const double pitch_rad = sc.feed_pitch_mm * 1e-3 / cfg_.disc_radius_m;
  while (disc_angle_rad >= next_pickup_angle_rad_) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const bool missed = u01(rng_) * 100.0 < sc.feed_miss_pct;
    Seedling s;
    s.diameter_mm = sc.diameter_min_mm + (sc.diameter_max_mm - sc.diameter_min_mm) * u01(rng_);
    s.length_mm = sc.length_min_mm + (sc.length_max_mm - sc.length_min_mm) * u01(rng_);
    std::normal_distribution<double> strength(sc.strength_mean_N, sc.strength_sd_N);
    s.strength_N = std::max(40.0, strength(rng_));
    if (sc.force_model.loaded) {
      // The DEM's first peak for this diameter, spread as the measured peaks are.
      const double cv = sc.strength_sd_N / sc.strength_mean_N;
      s.strength_N = sc.force_model.peak_force(s.diameter_mm) *
                     std::max(0.3, 1.0 + cv * (s.strength_N - sc.strength_mean_N) /
                                             std::max(1e-9, sc.strength_sd_N));
    }
    s.pickup_angle_rad = next_pickup_angle_rad_;
    s.pickup_time_s = now.t_s;
    next_pickup_angle_rad_ += pitch_rad;
    if (!missed) seedlings_.push_back(s);
  }
  // Compression while in the nip: the clamp force times the local contact factor.
  if (!seedlings_.empty()) {
    Seedling& s = seedlings_.back();
    if (now.t_s - s.pickup_time_s <= mc.nip_time_s) {
      s.peak_force_N = std::max(s.peak_force_N, clamp_force_N * contact_area_factor());
      s.damaged = s.peak_force_N > s.strength_N;
      if (sc.force_model.loaded) {
        // Past its first peak the wall collapses: the compression jumps past delta_p.
        const SeedlingForceModel& m = sc.force_model;
        s.peak_compression_mm = s.damaged
                                    ? std::max(m.peak_displacement(s.diameter_mm),
                                               m.compression_mm(s.diameter_mm, s.peak_force_N))
                                    : m.compression_mm(s.diameter_mm, s.peak_force_N);
      }
    }
  }
  const double carry_rad = mc.carry_angle_deg / kDegPerRad;
  while (next_release_ < seedlings_.size() &&
         disc_angle_rad >= seedlings_[next_release_].pickup_angle_rad + carry_rad) {
    Seedling& s = seedlings_[next_release_++];
    const double sigma =
        now.v_mps > 0.005 ? cfg_.disc_radius_m * now.omega_radps / now.v_mps : mc.optimum_sigma;
    s.planted = true;
    s.release_time_s = now.t_s;
    s.x_m = now.x_m;
    s.sigma_at_release = sigma;
    s.depth_at_release_mm = now.depth_mm;
    std::normal_distribution<double> noise(0.0, 1.0);
    s.tilt_deg = std::abs(tilt_deg(now, sigma) + sc.tilt_noise_deg * noise(rng_) +
                          vibration_tilt_deg * noise(rng_) + 0.15 * now.terrain_mm * noise(rng_) +
                          0.05 * (s.length_mm - 196.7) * noise(rng_));
  }
}

double SeedlingProcess::tilt_deg(const ReleaseConditions& c, double sigma) {
  const MechanismConfig& mc = cfg_.mechanism;
  const double a = mc.release_angle_deg / kDegPerRad;
  // Horizontal velocity of the clamp point relative to the soil at release, over v:
  // 1 - sigma cos(a); the soil backflow pushes the root forward in proportion to depth.
  const double backflow =
      (mc.optimum_sigma * std::cos(a) - 1.0) * std::max(0.0, c.depth_mm) / 102.0;
  const double relative = 1.0 - sigma * std::cos(a) + backflow;
  const double vertical = std::max(0.05, sigma * std::sin(a));
  const double kinematic =
      mc.kinematic_gain * std::atan(std::abs(relative) / vertical) * kDegPerRad;
  // A weak hold lets the seedling deflect at the clamp point.
  const double hold = std::max(0.0, c.clamp_force_N) * std::sqrt(mc.contact_area_mm2 / 255.0);
  const double clamp = 12.0 * std::exp(-hold / 45.0);
  return kinematic + clamp;
}

}  // namespace planter::sim
