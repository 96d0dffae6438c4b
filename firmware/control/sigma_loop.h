#pragma once
// Disc speed follows ground speed by distance travelled: the disc angle is held at
// sigma * distance / R, so sigma = R*omega/v holds through acceleration, stops and restarts.
// Feed-forward sigma*v/R plus PI on the angle error: the integral takes out the steady lag a
// dragging drive leaves (friction, dead zone). Anti-windup (Astrom and Hagglund, Advanced PID
// Control, 2006, Sec. 3.5): no integration while the command is limited, and the reference
// itself never runs more than max_lag_rad ahead of the disc, so a disc that cannot keep up
// (the machine faster than the disc's top speed) does not race to catch up afterwards.

namespace planter {

struct SigmaLoopConfig {
  double sigma = 1.5;
  double disc_radius_m = 0.300;
  double angle_gain_per_s = 3.0;  // disc angle error -> speed correction
  // The PI's zero at 0.2 rad/s, a fifteenth of the 3 rad/s crossover: it takes out a steady
  // lag without eating the phase margin (one value, chosen so; docs/control.md).
  double angle_integral_per_s2 = 0.6;
  // Assumed: 3 mm at the rim, a tenth of a spacing. Below it the integral rests, so the
  // nominal field (its error well inside) runs as the proportional loop did.
  double integral_dead_band_rad = 0.01;
  double omega_max_radps = 1.2;
  // The most the disc may lag its reference: one clamp pitch at the rim (the loader sets it
  // from the machine's pitch and radius). Beyond it the seedlings are missed, not caught up.
  double max_lag_rad = 0.1475;
  // The paper's drive for comparison (planter-sim robustness): the disc at a fixed ratio from
  // the soil wheel, as its chain does, with no correction of the angle.
  bool fixed_ratio = false;
};

// What the loop saw this tick, for the alarms (firmware/supervisor/loop_alarms.h).
struct SigmaStatus {
  bool too_fast = false;  // sigma v / R above the disc's top speed
  bool lag_held = false;  // the reference was held back at max_lag_rad
  double lag_rad = 0;     // the disc's angle behind its reference
};

class SigmaLoop {
 public:
  explicit SigmaLoop(const SigmaLoopConfig& config) : cfg_(config) {}

  // Latches the reference so the disc starts from where it is.
  void engage(double distance_m, double disc_angle_rad);
  // Returns the disc speed command in rad/s (never negative: the disc does not run back).
  double update(double distance_m, double ground_speed_mps, double disc_angle_rad, double dt_s);

  [[nodiscard]] double angle_error_rad() const { return status_.lag_rad; }
  [[nodiscard]] const SigmaStatus& status() const { return status_; }
  [[nodiscard]] double sigma_seen(double omega_radps, double ground_speed_mps) const;
  // The fastest the machine may go for the disc to hold sigma: omega_max R / sigma.
  [[nodiscard]] double top_ground_speed_mps() const {
    return cfg_.omega_max_radps * cfg_.disc_radius_m / cfg_.sigma;
  }

 private:
  SigmaLoopConfig cfg_;
  double distance0_m_ = 0.0;
  double angle0_rad_ = 0.0;
  double integral_radps_ = 0.0;
  SigmaStatus status_;
};

}  // namespace planter
