#pragma once
// Roller clamp force: feed-forward through the nominal clamp law plus PI trim on the load
// cell, and a ceiling held on two paths: the load cell, and the roller's position through the
// clamp law (so a load cell that reads low cannot push the lips past the ceiling).
// Anti-windup by back-calculation (Astrom and Hagglund, Advanced PID Control, 2006, Sec. 3.5):
// when the command is limited, the integral is set to what gives the limited command, so the
// loop neither winds up into a limit nor latches at one.

#include "firmware/control/stem_reader.h"

namespace planter {

struct ClampLoopConfig {
  double setpoint_N = 90.0;
  // The board derives the ceiling from the stems' strength (config/clamp_ceiling.h); this value
  // serves a loop built without a board (the unit tests).
  double ceiling_N = 120.0;
  double ramp_N_per_s = 60.0;  // set-point ramp at start
  // PI gains, set for a crossover near 8 rad/s on the nominal law's stiffness at 90 N
  // (29 N/mm): well above the seedlings' passing (2 Hz at the paper's speed) and below the
  // roller's 0.05 s lag and the two ticks of the load cell's path (docs/control.md).
  double kp_mm_per_N = 0.017;
  double ki_mm_per_Ns = 0.28;
  // The stem in the nip, read each tick (stem_reader.h): what it adds to the law's compression
  // goes into the feed-forward, and with per_stem_grip each stem is gripped under its own
  // ceiling: the machine's ceiling, held by the reference stem, over the stem's diameter
  // relative to it. The nip loads a stem over contact area / diameter of its length, so a
  // thicker one carries more per millimetre at the same force; the paper measures no relation
  // of strength to diameter, so none is taken (assumed; docs/control.md). Off: one set-point.
  StemReaderConfig stem;
  bool per_stem_grip = true;
  // A collapse seen says this batch is weaker than the ceiling assumes: every stem's ceiling is
  // lowered by this share, thickest stems first (theirs is lowest), and comes back at the rate
  // below. In balance one collapse in 1 / (rate / share) = 50 s: about 1 % of the stems at the
  // paper's pace of two a second. Set once (assumed), not tuned. Never below half the machine's
  // ceiling: 60 N, where the sweep's trade-off has uprightness some 7 points under its plateau,
  // so the soil's grip is given up no further (docs/control.md).
  double collapse_backoff = 0.05;
  double backoff_recovery_per_s = 0.001;
  double backoff_floor = 0.5;
  double position_min_mm = 0.0;
  double position_max_mm = 12.0;
  double release_position_mm = 0.0;  // roller position when not clamping
  // Nominal clamp model used for feed-forward and the ceiling's second path: F = k (x - x0)^n.
  double model_k_N = 14.85;
  double model_x0_mm = 2.0;
  double model_n = 1.3;
};

// What the loop saw this tick, for the alarms (firmware/supervisor/loop_alarms.h).
struct ClampStatus {
  bool clamping = false;
  bool ramped = false;       // the set-point has reached its target
  bool at_travel = false;    // the command is held at the roller's travel or the law's ceiling
  bool ceiling = false;      // either path above the ceiling's margin
  double model_force_N = 0;  // the clamp law at the roller's measured position
  double measured_N = 0;
  bool stem_gave_way = false;  // a collapse seen this tick (damage seen)
};

class ClampForceLoop {
 public:
  explicit ClampForceLoop(const ClampLoopConfig& config) : cfg_(config) {}

  void reset();
  // Returns the roller position command in mm. `enabled` false -> release position. The rim's
  // speed tells how soon a stem coming under the roller is in (StemReaderConfig::entry_mm).
  double update(double force_measured_N, double roller_mm, double rim_speed_mm_per_s, double dt_s,
                bool enabled);

  [[nodiscard]] double setpoint_N() const { return ramped_setpoint_N_; }
  // Whether the stem's reading may set its grip: not while the load cell and the roller disagree
  // (warning::kLoadCellDisagrees), when the law it reads through is not the lips'.
  void set_stem_reading_trusted(bool trusted) { stem_trusted_ = trusted; }
  // The force to clamp at (an increase ramps, a decrease is taken at once).
  void set_target_N(double target_N) { cfg_.setpoint_N = target_N; }
  [[nodiscard]] double target_N() const { return cfg_.setpoint_N; }
  // What the set-point ramps to this tick: the target under the stem's ceiling.
  [[nodiscard]] double aim_N() const { return aim_N_; }
  [[nodiscard]] double trim_mm() const { return integral_mm_; }
  [[nodiscard]] bool ceiling_active() const { return status_.ceiling; }
  [[nodiscard]] const ClampStatus& status() const { return status_; }
  // Position at which the nominal model gives `force_N`, and the model's force at a position.
  [[nodiscard]] double model_position_mm(double force_N) const;
  [[nodiscard]] double model_force_N(double position_mm) const;
  // The law's slope (N/mm) at a roller position, floored where the law is flat.
  [[nodiscard]] double model_slope_N_per_mm(double position_mm) const;
  [[nodiscard]] const StemReader& stem() const { return stem_; }
  // The force this stem may be gripped with: the machine's ceiling over its diameter's ratio to
  // the reference (never above the ceiling); the set-point stays below it by 5 %.
  [[nodiscard]] double stem_ceiling_N(double rim_speed_mm_per_s) const;
  // The share of the ceiling the collapses seen have left (1: none lately).
  [[nodiscard]] double ceiling_share() const { return ceiling_share_; }

 private:
  ClampLoopConfig cfg_;
  double ramped_setpoint_N_ = 0.0;
  double integral_mm_ = 0.0;
  double aim_N_ = 0.0;
  bool stem_trusted_ = true;
  ClampStatus status_;
  StemReader stem_{cfg_.stem};
  // Kept while the clamp opens and closes: it is the batch's, not the stem's.
  double ceiling_share_ = 1.0;

  // Each collapse seen this tick lowers every stem's ceiling; the share recovers with time.
  void learn_from_collapses(long new_collapses, double dt_s);
};

}  // namespace planter
