#include "firmware/control/clamp_force_loop.h"

#include <algorithm>
#include <cmath>

namespace planter {

void ClampForceLoop::reset() {
  ramped_setpoint_N_ = 0.0;
  integral_mm_ = 0.0;
  ceiling_active_ = false;
}

double ClampForceLoop::model_position_mm(double force_N) const {
  if (force_N <= 0.0) return cfg_.model_x0_mm;
  return cfg_.model_x0_mm + std::pow(force_N / cfg_.model_k_N, 1.0 / cfg_.model_n);
}

double ClampForceLoop::update(double force_N, double dt_s, bool enabled) {
  if (!enabled) {
    reset();
    return cfg_.release_position_mm;
  }
  // Never aim closer than 5 % below the ceiling.
  const double target = std::min(cfg_.setpoint_N, 0.95 * cfg_.ceiling_N);
  ramped_setpoint_N_ = std::min(target, ramped_setpoint_N_ + cfg_.ramp_N_per_s * dt_s);
  const double error = ramped_setpoint_N_ - force_N;

  const double feed_forward = model_position_mm(ramped_setpoint_N_);
  // The ceiling as a position: the model's ceiling position corrected by the learned trim.
  const double ceiling_position = model_position_mm(0.97 * cfg_.ceiling_N) + integral_mm_;
  double command = feed_forward + integral_mm_ + cfg_.kp_mm_per_N * error;
  const double upper = std::min(cfg_.position_max_mm, ceiling_position);
  const bool saturated_high = command >= upper;
  const bool saturated_low = command <= cfg_.position_min_mm;
  // Conditional integration: do not wind up into a limit.
  if (!(saturated_high && error > 0.0) && !(saturated_low && error < 0.0)) {
    integral_mm_ += cfg_.ki_mm_per_Ns * error * dt_s;
  }
  ceiling_active_ = force_N > 0.97 * cfg_.ceiling_N;
  if (ceiling_active_) {
    // Measured force near the ceiling: back off at once, proportionally to the excess.
    const double excess = force_N - 0.97 * cfg_.ceiling_N;
    integral_mm_ -= 0.02 * excess + 0.05;
    command = std::min(command, feed_forward + integral_mm_);
  }
  return std::clamp(command, cfg_.position_min_mm, std::max(cfg_.position_min_mm, upper));
}

}  // namespace planter
