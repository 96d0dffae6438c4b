#pragma once
// Disc speed follows ground speed by distance travelled: the disc angle is held at
// sigma * distance / R, so sigma = R*omega/v holds through acceleration, stops and restarts.
// Feed-forward sigma*v/R plus a correction on the angle error (proportional; an integral is
// there but off, see angle_integral_per_s2). Anti-windup (Astrom and Hagglund, Advanced PID
// Control, 2006, Sec. 3.5): no integration while the command is limited, and the reference
// itself never runs more than max_lag_rad() ahead of the disc, so a disc that cannot keep up
// (the machine faster than the disc's top speed) does not race to catch up afterwards.

namespace planter {

struct SigmaLoopConfig {
  double sigma = 1.5;
  double disc_radius_m = 0.300;
  double angle_gain_per_s = 3.0;  // disc angle error -> speed correction
  // An integral on the angle, off: with 0.6 /s^2 (its zero a fifteenth of the crossover) a
  // disc drive with 4 N m of Coulomb friction hunted (stick-slip under integral action,
  // Armstrong-Helouvry, Dupont and Canudas de Wit, Automatica 30(7), 1994) and the suite's
  // worst sigma window went 2.08 -> 6.11 %. The steady lag friction leaves shifts every
  // seedling alike and does not change sigma; the lag alarm tells the operator of it.
  double angle_integral_per_s2 = 0.0;
  // When on, only a lag beyond this is integrated (assumed: 3 mm at the rim).
  double integral_dead_band_rad = 0.01;
  double omega_max_radps = 1.2;
  // The clamps' pitch at the rim (the loader sets it from the machine's pitch and radius), and
  // the most the disc may lag its reference, in pitches: a lag within it is caught up (a
  // seedling or two closer together), beyond it seedlings are missed, not thrown in later.
  // One: 3 gave the same figures in every case of the suite but the one past the disc's top
  // speed, where it caught up more (sigma RMS 16.1 against 15.6 %).
  double clamp_pitch_rad = 0.1475;
  double max_lag_pitches = 1.0;
  [[nodiscard]] double max_lag_rad() const { return max_lag_pitches * clamp_pitch_rad; }
  // The paper's drive for comparison (planter-sim robustness): the disc at a fixed ratio from
  // the soil wheel, as its chain does, with no correction of the angle.
  bool fixed_ratio = false;
};

// What the loop saw this tick, for the alarms (firmware/supervisor/loop_alarms.h).
struct SigmaStatus {
  bool too_fast = false;  // sigma v / R above 90 % of the disc's top speed
  bool lag_held = false;  // the reference was held back at max_lag_rad()
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
