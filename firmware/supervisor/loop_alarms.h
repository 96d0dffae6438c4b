#pragma once
// The loops' named alarms (warning:: bits in supervisor.h): each rises when its condition has
// held for its delay, short enough that the operator hears of a loop leaving its goal within
// a second (firmware/control/loop_goals.h), and stays up for hold_s after it clears so that a
// glance at the console catches it. Pure logic, no allocation: one update per tick.
#include <cstdint>

#include "firmware/control/clamp_force_loop.h"
#include "firmware/control/furrow_depth_loop.h"
#include "firmware/control/loop_goals.h"
#include "firmware/control/sigma_loop.h"
#include "firmware/sensing/planting_monitor.h"

namespace planter {

struct LoopAlarmConfig {
  double hold_s = 2.0;  // assumed: long enough to be seen on a console refreshed at 2 Hz
  // The load cell and the roller's position through the clamp law disagree by more than this
  // share of the law's force plus the offset (assumed: lips differ batch to batch by 10-30 %).
  double disagree_share = 0.10;
  double disagree_offset_N = 4.0;
  // The slow part of the same disagreement: its mean over drift_tau_s moving by more than
  // drift_N from where it settled after the start is a load cell drifting (or lips changing
  // slowly) while the two paths still agree within the fast threshold above. drift_N is set
  // below where a drift takes the grip out of its band (the band is 9 N at 90 N and thick
  // stems add up to about 5 N to a seedling's mean grip, so about 4 N): one value, chosen so;
  // the nominal field's slow mean stays inside it (no alarm in the 30 m run).
  double drift_tau_s = 10.0;
  double drift_settle_s = 20.0;
  double drift_N = 3.0;
  // A grip below this share of the set-point lets a seedling slide out (assumed, 0.3-0.7).
  double weak_grip_share = 0.5;
  // From pickup to release, the disc turns this far (the paper's carry, 150 deg): empty clamps
  // within it of a weak grip are seedlings dropped, not an empty belt.
  double carry_rad = 2.618;
  double clamp_pitch_rad = 0.1475;  // the loader sets it: the machine's pitch over the radius
  double band_pct = kLoopGoals.clamp.band_pct;      // the clamp's goal band
  double depth_band_mm = kLoopGoals.depth.band_mm;  // the depth's goal band
};

struct LoopAlarmInputs {
  bool running = false;
  double dt_s = 0.01;
  double disc_angle_rad = 0;
  double clamp_setpoint_N = 0;
  SigmaStatus sigma;
  ClampStatus clamp;
  DepthStatus depth;
  bool empty_belt = false;   // the planting monitor's
  bool wheel_alone = false;  // a GNSS receiver is fitted and its speed is not in use
};

class LoopAlarms {
 public:
  explicit LoopAlarms(const LoopAlarmConfig& config) : cfg_(config) {}
  void reset();
  // The warning:: bits that hold now.
  std::uint32_t update(const LoopAlarmInputs& in);

 private:
  struct Timer {  // a condition that must hold for `delay_s` to raise, then holds for hold_s
    double on_s = 0, off_s = 0;
    bool raised = false;
    bool update(bool condition, double dt_s, double delay_s, double hold_s);
  };
  LoopAlarmConfig cfg_;
  Timer too_fast_, lagging_, short_, disagrees_, ceiling_, depth_, depth_off_, gave_way_,
      wheel_alone_;
  double weak_grip_angle_rad_ = -1e9;
  double gripping_s_ = 0;      // since the grip began
  double disagree_lp_N_ = 0;   // the disagreement's slow mean
  double disagree_ref_N_ = 0;  // ... where it settled after the start
  bool drift_ref_taken_ = false;
};

}  // namespace planter
