#include "firmware/control/sigma_loop.h"

#include <algorithm>
#include <cmath>

namespace planter {

void SigmaLoop::engage(double distance_m, double disc_angle_rad) {
  distance0_m_ = distance_m;
  angle0_rad_ = disc_angle_rad;
  integral_radps_ = 0.0;
  status_ = SigmaStatus{};
}

double SigmaLoop::update(double distance_m, double ground_speed_mps, double disc_angle_rad,
                         double dt_s) {
  const double k = cfg_.sigma / cfg_.disc_radius_m;
  const double feed_forward = k * std::max(0.0, ground_speed_mps);
  // Said a tenth before the disc's top: the clamp falls behind the seedlings' rate first.
  status_.too_fast = feed_forward > 0.9 * cfg_.omega_max_radps;
  if (cfg_.fixed_ratio) return std::clamp(feed_forward, 0.0, cfg_.omega_max_radps);
  double error = angle0_rad_ + k * (distance_m - distance0_m_) - disc_angle_rad;
  // The reference governor: beyond max_lag the reference slides along with the disc.
  const double max_lag_rad = cfg_.max_lag_rad();
  status_.lag_held = error > max_lag_rad;
  if (status_.lag_held) {
    angle0_rad_ -= error - max_lag_rad;
    error = max_lag_rad;
  }
  status_.lag_rad = error;
  const double command = feed_forward + cfg_.angle_gain_per_s * error + integral_radps_;
  const double limited = std::clamp(command, 0.0, cfg_.omega_max_radps);
  // Conditional integration: not while limited in the direction the error pushes.
  const bool pushing_limit =
      (command > limited && error > 0.0) || (command < limited && error < 0.0);
  // Only a lag past the dead band and within a pitch is integrated: the field's own wander
  // (speed, slip) stays with the proportional term, and so does a start's transient lag (an
  // integral of it overshoots once the disc breaks free); a dragging drive's steady lag goes
  // to the integral.
  const double beyond = std::abs(error) - cfg_.integral_dead_band_rad;
  if (!pushing_limit && beyond > 0.0 && std::abs(error) < cfg_.clamp_pitch_rad)
    integral_radps_ += cfg_.angle_integral_per_s2 * std::copysign(beyond, error) * dt_s;
  return limited;
}

double SigmaLoop::sigma_seen(double omega_radps, double ground_speed_mps) const {
  if (std::abs(ground_speed_mps) < 1e-4) return 0.0;
  return cfg_.disc_radius_m * omega_radps / ground_speed_mps;
}

}  // namespace planter
