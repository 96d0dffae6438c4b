#include "sim/plant/seedling_process.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace planter::sim {
namespace {
constexpr double kDegPerRad = 57.29577951308232;
}

double nip_load_factor(const PlantConfig& config, double diameter_mm) {
  return config.seedlings.strength_test_length_mm * 1e-3 /
         std::max(1e-6, held_length_m(config.mechanism, diameter_mm));
}

double strength_size_factor(const SeedlingConfig& seedlings, double diameter_mm) {
  return std::pow(diameter_mm / seedlings.reference_diameter_mm,
                  seedlings.strength_diameter_exponent);
}

SeedlingProcess::SeedlingProcess(const PlantConfig& config, std::uint64_t seed)
    : cfg_(config), rng_(seed) {
  seedlings_.reserve(2048);
  const SeedlingConfig& sc = cfg_.seedlings;
  if (sc.force_model.loaded)
    nip_.emplace(sc.force_model, sc.reference_diameter_mm,
                 1.0 / nip_load_factor(cfg_, sc.reference_diameter_mm),
                 cfg_.drive.seedling_thickness_gain);
}

double SeedlingProcess::nip_share(const Seedling& s, const NipClock& now) const {
  const double entry_mm = cfg_.mechanism.nip_entry_mm;
  if (!(entry_mm > 0.0)) return 1.0;
  const double in_mm = (now.disc_angle_rad - s.pickup_angle_rad) * cfg_.disc_radius_m * 1e3;
  const double out_mm = (s.pickup_time_s + cfg_.mechanism.nip_time_s - now.t_s) *
                        std::abs(now.omega_radps) * cfg_.disc_radius_m * 1e3;
  return std::clamp(std::min(in_mm, out_mm) / entry_mm, 0.0, 1.0);
}

std::optional<SeedlingProcess::NipForce> SeedlingProcess::nip_force(double gap_mm, double k_N,
                                                                    double n, const NipClock& now,
                                                                    double guess_N) {
  if (!nip_ || seedling_in_nip(now.t_s) == 0) return std::nullopt;
  Seedling& s = seedlings_.back();
  NipStem& stem = s.nip;
  stem.share = nip_share(s, now);
  const double f = nip_->force_N(gap_mm, k_N, n, stem, guess_N);
  return NipForce{f, nip_->added_compression_mm(stem, f)};
}

double SeedlingProcess::nip_thickness_mm(const NipClock& now) const {
  if (seedlings_.empty()) return 0.0;
  const Seedling& s = seedlings_.back();
  if (now.t_s - s.pickup_time_s > cfg_.mechanism.nip_time_s) return 0.0;
  return nip_share(s, now) * std::max(0.0, (s.diameter_mm - cfg_.seedlings.reference_diameter_mm) *
                                               cfg_.drive.seedling_thickness_gain);
}

std::size_t SeedlingProcess::seedling_in_nip(double t_s) const {
  if (seedlings_.empty()) return 0;
  const Seedling& s = seedlings_.back();
  return t_s - s.pickup_time_s > cfg_.mechanism.nip_time_s ? 0 : seedlings_.size();
}

Seedling SeedlingProcess::sample(double t_s) {
  const SeedlingConfig& sc = cfg_.seedlings;
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  Seedling s;
  s.diameter_mm = sc.diameter_min_mm + (sc.diameter_max_mm - sc.diameter_min_mm) * u01(rng_);
  s.length_mm = sc.length_min_mm + (sc.length_max_mm - sc.length_min_mm) * u01(rng_);
  // Lognormal strength (config/stem_strength.h), one standard normal draw.
  std::normal_distribution<double> z(0.0, 1.0);
  s.strength_N = config::lognormal_strength_N(sc.strength_mean(), sc.strength_sd(), z(rng_)) *
                 strength_size_factor(sc, s.diameter_mm);
  if (nip_) {
    s.nip.diameter_mm = s.diameter_mm;
    s.nip.load_factor = 1.0 / nip_load_factor(cfg_, s.diameter_mm);
    s.nip.peak_N = s.strength_N * s.nip.load_factor;
  }
  s.pickup_angle_rad = next_pickup_angle_rad_;
  s.pickup_time_s = t_s;
  return s;
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
  if (!(pitch_rad > 0.0)) return;  // no clamps to fill (the Plant sets the machine's pitch)
  while (disc_angle_rad >= next_pickup_angle_rad_) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const bool missed = u01(rng_) * 100.0 < sc.feed_miss_pct;
    // Drawn only when doubles are on, so a scenario without them keeps its random stream.
    const bool doubled =
        !missed && sc.feed_double_pct > 0.0 && u01(rng_) * 100.0 < sc.feed_double_pct;
    Seedling s = sample(now.t_s);
    next_pickup_angle_rad_ += pitch_rad;
    if (missed) continue;
    seedlings_.push_back(s);
    if (doubled) {
      // A second seedling in the same clamp, beside the first along the rim: from 1.5 of its
      // diameter to half a pitch behind it (closer and the two would be one stem).
      Seedling second = sample(now.t_s);
      const double offset_mm = 1.5 * second.diameter_mm +
                               (0.5 * sc.feed_pitch_mm - 1.5 * second.diameter_mm) * u01(rng_);
      second.pickup_angle_rad =
          s.pickup_angle_rad + std::max(0.0, offset_mm) * 1e-3 / cfg_.disc_radius_m;
      second.doubled = true;
      seedlings_.push_back(second);
    }
  }
  // Compression while in the nip: the clamp force as the strength test's force. With the DEM's
  // law the stem is damaged when its wall has collapsed (the plant's nip solve, clamp_nip.h).
  if (!seedlings_.empty()) {
    Seedling& s = seedlings_.back();
    if (now.t_s - s.pickup_time_s <= mc.nip_time_s) {
      const double carried_N = nip_ ? s.nip.share * clamp_force_N : clamp_force_N;
      s.peak_force_N = std::max(s.peak_force_N, carried_N * nip_load_factor(cfg_, s.diameter_mm));
      if (nip_) {
        s.damaged = s.nip.collapsed;
        s.peak_compression_mm =
            std::max(s.peak_compression_mm, nip_->stem_compression_mm(s.nip, carried_N));
      } else {
        s.damaged = s.peak_force_N > s.strength_N;
      }
    }
  }
  const double carry_rad = mc.carry_angle_deg / kDegPerRad;
  while (next_release_ < seedlings_.size() &&
         disc_angle_rad >= seedlings_[next_release_].pickup_angle_rad + carry_rad) {
    Seedling& s = seedlings_[next_release_++];
    s.release_time_s = now.t_s;
    s.x_m = now.x_m;
    s.sigma_at_release = now.v_mps > 0.005 ? cfg_.disc_radius_m * now.omega_radps / now.v_mps
                                           : std::numeric_limits<double>::quiet_NaN();
    s.depth_at_release_mm = now.depth_mm;
    std::normal_distribution<double> noise(0.0, 1.0);
    ReleaseInput in;
    in.length_mm = s.length_mm;
    in.diameter_mm = s.diameter_mm;
    in.v_mps = now.v_mps;
    in.omega_radps = now.omega_radps;
    in.depth_mm = now.depth_mm;
    in.clamp_force_N = now.clamp_force_N;
    // What the release mechanics leave out, and the machine's vibration, as a scatter.
    in.scatter_deg = sc.tilt_noise_deg * noise(rng_) + vibration_tilt_deg * noise(rng_);
    s.release = release_seedling(cfg_, in);
    s.tilt_deg = s.release.tilt_deg;
    s.planted = !s.release.fell_in_carry;  // dropped from the clamp: a skip
  }
}

}  // namespace planter::sim
