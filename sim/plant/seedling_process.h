#pragma once
// Seedlings from feed to furrow: each is picked up by the disc at the roller nip (where it is
// compressed and may be damaged), carried through the carry angle and released; its tilt in
// the furrow comes from the release mechanics (seedling_release.h).
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "sim/plant/clamp_nip.h"
#include "sim/plant/plant_config.h"
#include "sim/plant/seedling_release.h"

namespace planter::sim {

// The nip's load on a seedling as the strength test's force: the lips spread the clamp force
// over the held length w (contact area / diameter), the test's plates over their own length, so
// the wall sees the same line load (N/mm) when F_test = F L_test / w. A thin-walled tube
// crushed between plates fails at a line load (ring crushing: Timoshenko and Gere, "Theory of
// Elastic Stability", ch. 7, the ring's collapse load per unit length).
double nip_load_factor(const PlantConfig& config, double diameter_mm);

// A stem's strength over its lognormal draw: (d / d_ref)^exponent, the assumed power of the
// diameter (not the DEM's slope of its peak, which came from its particle scaling).
double strength_size_factor(const SeedlingConfig& seedlings, double diameter_mm);

struct Seedling {
  double diameter_mm = 0;
  double length_mm = 0;
  double strength_N = 0;
  double pickup_angle_rad = 0;
  double pickup_time_s = 0;
  double peak_force_N = 0;         // largest radial compression while in the nip
  double peak_compression_mm = 0;  // its radial compression then (with a DEM force model)
  NipStem nip;                     // the stem as the nip's law sees it (with a DEM force model)
  bool damaged = false;
  bool planted = false;
  bool doubled = false;  // the second seedling the feed put into one clamp
  double release_time_s = 0;
  double x_m = 0;       // position along the row where it was planted
  double tilt_deg = 0;  // from vertical, + top forward; 90 lodged
  ReleaseOutcome release;
  double sigma_at_release = 0;  // NaN when released standing
  double depth_at_release_mm = 0;
};

struct ReleaseConditions {
  double t_s, x_m, v_mps, omega_radps, depth_mm, clamp_force_N, terrain_mm;
};

class SeedlingProcess {
 public:
  SeedlingProcess(const PlantConfig& config, std::uint64_t seed);

  // Called every step with the disc's angle; picks up and releases seedlings.
  void step(double disc_angle_rad, double clamp_force_N, const ReleaseConditions& now,
            double vibration_tilt_deg);
  // Where the nip is now: the time and the disc's angle and speed, for how far the lips have
  // closed on the stem in it (mechanism.nip_entry_mm).
  struct NipClock {
    double t_s = 0;
    double disc_angle_rad = 0;
    double omega_radps = 0;
  };
  // Extra lip compression (mm) from the seedling currently in the nip, for the clamp model
  // without the DEM's law: its thickness over the reference diameter's.
  [[nodiscard]] double nip_thickness_mm(const NipClock& now) const;
  // With the DEM's law (clamp_nip.h): the clamp's force at the law's gap x - x0 (law k_N, n)
  // with the stem in the nip now, which may collapse; nullopt when the nip is empty or the
  // scenario names no law. `added_mm` is what the stem adds to the law's compression.
  struct NipForce {
    double force_N;
    double added_mm;
  };
  [[nodiscard]] std::optional<NipForce> nip_force(double gap_mm, double k_N, double n,
                                                  const NipClock& now, double guess_N);
  // The seedling in the nip now, counted from 1 (0: the nip is empty).
  [[nodiscard]] std::size_t seedling_in_nip(double t_s) const;

  [[nodiscard]] const std::vector<Seedling>& seedlings() const { return seedlings_; }
  void set_feed_miss_pct(double pct) { cfg_.seedlings.feed_miss_pct = pct; }
  // How many have been released so far (seedlings()[0, released()) are planted).
  [[nodiscard]] std::size_t released() const { return next_release_; }

 private:
  // How far the lips have closed on `s` (0-1): in over the rim's first nip_entry_mm past its
  // pickup, out over the nip time's last nip_entry_mm at the rim's speed now.
  [[nodiscard]] double nip_share(const Seedling& s, const NipClock& now) const;
  // A seedling as the feed delivers it to the clamp now, drawn from the configured spread.
  Seedling sample(double t_s);

  PlantConfig cfg_;
  std::optional<ClampNip> nip_;  // with the DEM's law
  std::mt19937_64 rng_;
  std::vector<Seedling> seedlings_;
  double next_pickup_angle_rad_ = 0.0;
  std::size_t next_release_ = 0;
  bool started_ = false;
};

}  // namespace planter::sim
