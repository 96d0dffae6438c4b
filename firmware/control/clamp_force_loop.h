#pragma once
// Roller clamp force: feed-forward through the nominal clamp law plus PI trim on the load
// cell, and a ceiling held on two paths: the load cell, and the roller's position through the
// clamp law (so a load cell that reads low cannot push the lips past the ceiling).
// Anti-windup by back-calculation (Astrom and Hagglund, Advanced PID Control, 2006, Sec. 3.5):
// when the command is limited, the integral is set to what gives the limited command, so the
// loop neither winds up into a limit nor latches at one.

namespace planter {

struct ClampLoopConfig {
  double setpoint_N = 90.0;
  double ceiling_N = 120.0;
  double ramp_N_per_s = 60.0;  // set-point ramp at start
  // PI gains, set for a crossover near 8 rad/s on the nominal law's stiffness at 90 N
  // (29 N/mm): well above the seedlings' passing (2 Hz at the paper's speed) and below the
  // roller's 0.05 s lag and the two ticks of the load cell's path (docs/control.md).
  double kp_mm_per_N = 0.017;
  double ki_mm_per_Ns = 0.28;
  // A stem entering or leaving the nip steps the force while the roller stands (the nip's law,
  // sim/plant/clamp_nip.h): a step beyond this, less what the roller's own move explains through
  // the law's slope, is read as that stem's added compression and taken into the trim at once
  // (docs/control.md). Above the load cell's noise between two ticks (1 N each: 1.4 N) by four
  // times; 0 turns the reading off.
  double stem_step_N = 6.0;
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
};

class ClampForceLoop {
 public:
  explicit ClampForceLoop(const ClampLoopConfig& config) : cfg_(config) {}

  void reset();
  // Returns the roller position command in mm. `enabled` false -> release position.
  double update(double force_measured_N, double roller_mm, double dt_s, bool enabled);

  [[nodiscard]] double setpoint_N() const { return ramped_setpoint_N_; }
  // The force to clamp at (an increase ramps, a decrease is taken at once).
  void set_target_N(double target_N) { cfg_.setpoint_N = target_N; }
  [[nodiscard]] double target_N() const { return cfg_.setpoint_N; }
  [[nodiscard]] double trim_mm() const { return integral_mm_; }
  [[nodiscard]] bool ceiling_active() const { return status_.ceiling; }
  [[nodiscard]] const ClampStatus& status() const { return status_; }
  // Position at which the nominal model gives `force_N`, and the model's force at a position.
  [[nodiscard]] double model_position_mm(double force_N) const;
  [[nodiscard]] double model_force_N(double position_mm) const;
  // The law's slope (N/mm) at a roller position, floored where the law is flat.
  [[nodiscard]] double model_slope_N_per_mm(double position_mm) const;
  // Stems read in the nip since the start (steps taken into the trim).
  [[nodiscard]] long stems_read() const { return stems_read_; }

 private:
  ClampLoopConfig cfg_;
  double ramped_setpoint_N_ = 0.0;
  double integral_mm_ = 0.0;
  ClampStatus status_;
  double last_force_N_ = 0.0, last_roller_mm_ = 0.0;
  bool has_last_ = false;
  long stems_read_ = 0;

  // The step a stem makes in the force, taken into the trim (stem_step_N).
  void read_stem(double force_N, double roller_mm, bool gripping);
};

}  // namespace planter
