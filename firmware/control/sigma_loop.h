#pragma once
// Disc speed follows ground speed by distance travelled: the disc angle is held at
// sigma * distance / R, so sigma = R*omega/v holds through acceleration, stops and restarts.

namespace planter {

struct SigmaLoopConfig {
  double sigma = 1.5;
  double disc_radius_m = 0.300;
  double angle_gain_per_s = 3.0;  // disc angle error -> speed correction
  double omega_max_radps = 1.2;
};

class SigmaLoop {
 public:
  explicit SigmaLoop(const SigmaLoopConfig& config) : cfg_(config) {}

  // Latches the reference so the disc starts from where it is.
  void engage(double distance_m, double disc_angle_rad);
  // Returns the disc speed command in rad/s (never negative: the disc does not run back).
  double update(double distance_m, double ground_speed_mps, double disc_angle_rad);

  [[nodiscard]] double angle_error_rad() const { return angle_error_rad_; }
  [[nodiscard]] double sigma_seen(double omega_radps, double ground_speed_mps) const;

 private:
  SigmaLoopConfig cfg_;
  double distance0_m_ = 0.0;
  double angle0_rad_ = 0.0;
  double angle_error_rad_ = 0.0;
};

}  // namespace planter
