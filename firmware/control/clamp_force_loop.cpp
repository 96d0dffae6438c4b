#include "firmware/control/clamp_force_loop.h"

#include <algorithm>
#include <cmath>

namespace planter {
namespace {
// Below this the law's inverse is steep and the load cell's noise reads as millimetres.
constexpr double kStemReadMinN = 10.0;
}  // namespace

void ClampForceLoop::reset() {
  ramped_setpoint_N_ = 0.0;
  integral_mm_ = 0.0;
  aim_N_ = 0.0;
  status_ = ClampStatus{};
  stem_.reset();
}

double ClampForceLoop::model_slope_N_per_mm(double position_mm) const {
  return cfg_.model_k_N * cfg_.model_n *
         std::pow(std::max(0.1, position_mm - cfg_.model_x0_mm), cfg_.model_n - 1.0);
}

double ClampForceLoop::stem_ceiling_N(double rim_speed_mm_per_s) const {
  const double d_mm = stem_.diameter_mm(rim_speed_mm_per_s);
  const double d_ref_mm = cfg_.stem.reference_diameter_mm;
  return ceiling_share_ * (d_mm > d_ref_mm ? cfg_.ceiling_N * d_ref_mm / d_mm : cfg_.ceiling_N);
}

void ClampForceLoop::learn_from_collapses(long new_collapses, double dt_s) {
  for (long i = 0; i < new_collapses; ++i) ceiling_share_ *= 1.0 - cfg_.collapse_backoff;
  ceiling_share_ =
      std::clamp(ceiling_share_ + cfg_.backoff_recovery_per_s * dt_s, cfg_.backoff_floor, 1.0);
}

double ClampForceLoop::model_position_mm(double force_N) const {
  if (force_N <= 0.0) return cfg_.model_x0_mm;
  return cfg_.model_x0_mm + std::pow(force_N / cfg_.model_k_N, 1.0 / cfg_.model_n);
}

double ClampForceLoop::model_force_N(double position_mm) const {
  const double compression = position_mm - cfg_.model_x0_mm;
  return compression > 0.0 ? cfg_.model_k_N * std::pow(compression, cfg_.model_n) : 0.0;
}

double ClampForceLoop::update(double force_N, double roller_mm, double rim_speed_mm_per_s,
                              double dt_s, bool enabled) {
  if (!enabled) {
    reset();
    return cfg_.release_position_mm;
  }
  // The stem in the nip, read once the lips carry a force the law resolves.
  const long collapses_before = stem_.collapses();
  if (force_N > kStemReadMinN) stem_.update(model_position_mm(force_N) - roller_mm, dt_s);
  const long new_collapses = stem_.collapses() - collapses_before;
  if (cfg_.per_stem_grip) learn_from_collapses(new_collapses, dt_s);
  // Never aim closer than 5 % below the ceiling (the stem's own, per_stem_grip); back off from
  // 3 % below the machine's.
  const bool per_stem = cfg_.per_stem_grip && stem_trusted_ && stem_.settled();
  const double ceiling_N = per_stem ? stem_ceiling_N(rim_speed_mm_per_s) : cfg_.ceiling_N;
  const double target = std::min(cfg_.setpoint_N, 0.95 * ceiling_N);
  aim_N_ = target;
  const double guard_N = 0.97 * cfg_.ceiling_N;
  ramped_setpoint_N_ = std::min(target, ramped_setpoint_N_ + cfg_.ramp_N_per_s * dt_s);
  const double error = ramped_setpoint_N_ - force_N;
  const double feed_forward = model_position_mm(ramped_setpoint_N_) - stem_.stem_ahead_mm();
  const bool ramped = ramped_setpoint_N_ >= target - 1e-9;

  // The ceiling's second path: the roller never goes past where the law gives the guard force,
  // whatever the load cell says. A fixed position: it does not move with the trim.
  const double upper = std::min(cfg_.position_max_mm, model_position_mm(guard_N));
  const double lower = cfg_.position_min_mm;
  double command = feed_forward + integral_mm_ + cfg_.kp_mm_per_N * error;
  // The first path: the load cell (or the law at the measured position) above the guard backs
  // the roller off from where it is, by the law's slope for the excess.
  const double model_N = model_force_N(roller_mm);
  const double seen_N = std::max(force_N, model_N);
  const bool ceiling = seen_N > guard_N;
  if (ceiling)
    command = std::min(command, roller_mm - (seen_N - guard_N) / model_slope_N_per_mm(roller_mm));
  const double limited = std::clamp(command, lower, std::max(lower, upper));
  const bool at_travel = command >= upper && error > 0.0;
  if (limited != command || ceiling) {
    // Back-calculation: the integral is what gives the limited command (no windup, no latch).
    integral_mm_ = limited - feed_forward - cfg_.kp_mm_per_N * error;
  } else {
    integral_mm_ += cfg_.ki_mm_per_Ns * error * dt_s;
  }
  status_ = {true, ramped, at_travel, ceiling, model_N, force_N, new_collapses > 0};
  return limited;
}

}  // namespace planter
