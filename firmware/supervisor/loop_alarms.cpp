#include "firmware/supervisor/loop_alarms.h"

#include <algorithm>
#include <cmath>

#include "firmware/supervisor/supervisor.h"

namespace planter {

bool LoopAlarms::Timer::update(bool condition, double dt_s, double delay_s, double hold_s) {
  if (condition) {
    on_s += dt_s;
    off_s = 0;
    if (on_s >= delay_s - 1e-9) raised = true;
  } else {
    on_s = 0;
    off_s += dt_s;
    if (off_s >= hold_s) raised = false;
  }
  return raised;
}

void LoopAlarms::reset() {
  too_fast_ = lagging_ = short_ = disagrees_ = ceiling_ = depth_ = depth_off_ = gave_way_ =
      wheel_alone_ = Timer{};
  weak_grip_angle_rad_ = -1e9;
  gripping_s_ = disagree_lp_N_ = disagree_ref_N_ = 0;
  drift_ref_taken_ = false;
}

std::uint32_t LoopAlarms::update(const LoopAlarmInputs& in) {
  const double dt = in.dt_s, hold = cfg_.hold_s;
  const bool run = in.running;
  std::uint32_t w = 0;
  // Sigma: the machine faster than the disc's top, or the disc held a pitch behind.
  if (too_fast_.update(run && in.sigma.too_fast, dt, 0.3, hold)) w |= warning::kTooFastForDisc;
  const bool behind = in.sigma.lag_held || in.sigma.lag_rad > 0.5 * cfg_.clamp_pitch_rad;
  if (lagging_.update(run && behind && !in.sigma.too_fast, dt, 0.5, hold))
    w |= warning::kDiscLagging;
  // Clamp: the roller at its travel with the force short of the band.
  const ClampStatus& c = in.clamp;
  const bool gripping = run && c.clamping && c.ramped;
  const bool short_of_band = c.measured_N < (1.0 - cfg_.band_pct / 100.0) * in.clamp_setpoint_N;
  if (short_.update(gripping && c.at_travel && short_of_band, dt, 0.3, hold))
    w |= warning::kClampShort;
  // Against the law alone: the stem's reading goes through the load cell, so it would take a
  // cell's error in as a stem until its baseline caught up (5 s): too late for the second.
  const double expected_N = c.model_force_N;
  const double disagreement = std::abs(c.measured_N - expected_N);
  bool disagree = disagreement > cfg_.disagree_share * expected_N + cfg_.disagree_offset_N;
  if (gripping) {
    gripping_s_ += dt;
    disagree_lp_N_ +=
        (c.measured_N - expected_N - disagree_lp_N_) * std::min(1.0, dt / cfg_.drift_tau_s);
    if (!drift_ref_taken_ && gripping_s_ >= cfg_.drift_settle_s) {
      disagree_ref_N_ = disagree_lp_N_;
      drift_ref_taken_ = true;
    }
    disagree =
        disagree || (drift_ref_taken_ && std::abs(disagree_lp_N_ - disagree_ref_N_) > cfg_.drift_N);
  }
  if (disagrees_.update(gripping && disagree, dt, 0.5, hold)) w |= warning::kLoadCellDisagrees;
  if (ceiling_.update(run && c.ceiling, dt, 0.1, hold)) w |= warning::kClampAtCeiling;
  // A stem's wall seen to give way (damage seen): at once, the tick it is seen.
  if (gave_way_.update(c.stem_gave_way, dt, 0.0, hold)) w |= warning::kStemGaveWay;
  // The GNSS fix lost or poor: at once, the fusion already waited its fix timeout (0.5 s).
  if (wheel_alone_.update(run && in.wheel_alone, dt, 0.0, hold)) w |= warning::kGnssLost;
  // Empty clamps: dropped seedlings when the grip was weak within a carry, else an empty belt.
  if (gripping && c.measured_N < cfg_.weak_grip_share * in.clamp_setpoint_N)
    weak_grip_angle_rad_ = in.disc_angle_rad;
  if (in.empty_belt) {
    const bool dropped =
        in.disc_angle_rad - weak_grip_angle_rad_ < cfg_.carry_rad + 6.0 * cfg_.clamp_pitch_rad;
    w |= dropped ? warning::kSeedlingsFalling : warning::kEmptyBelt;
  }
  // Depth: the opener held at an end stop with the depth out of its band.
  // Else the measured depth out of its band: the ground or the soil beat the loop.
  const DepthStatus& d = in.depth;
  const bool off = run && d.settled && std::abs(d.error_mm) > cfg_.depth_band_mm;
  if (depth_.update(off && d.at_end_stop, dt, 0.5, hold)) w |= warning::kDepthUnreachable;
  if (depth_off_.update(off && !d.at_end_stop, dt, 0.5, hold)) w |= warning::kDepthOffBand;
  return w;
}

}  // namespace planter
