#include "firmware/control/sigma_loop.h"

#include <algorithm>
#include <cmath>

namespace planter {

void SigmaLoop::engage(double distance_m, double disc_angle_rad) {
  distance0_m_ = distance_m;
  angle0_rad_ = disc_angle_rad;
  angle_error_rad_ = 0.0;
}

double SigmaLoop::update(double distance_m, double ground_speed_mps, double disc_angle_rad) {
  const double k = cfg_.sigma / cfg_.disc_radius_m;
  const double angle_ref = angle0_rad_ + k * (distance_m - distance0_m_);
  angle_error_rad_ = angle_ref - disc_angle_rad;
  const double feed_forward = k * std::max(0.0, ground_speed_mps);
  return std::clamp(feed_forward + cfg_.angle_gain_per_s * angle_error_rad_, 0.0,
                    cfg_.omega_max_radps);
}

double SigmaLoop::sigma_seen(double omega_radps, double ground_speed_mps) const {
  if (std::abs(ground_speed_mps) < 1e-4) return 0.0;
  return cfg_.disc_radius_m * omega_radps / ground_speed_mps;
}

}  // namespace planter
