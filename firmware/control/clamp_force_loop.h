#pragma once
// Roller clamp force: feed-forward through the nominal clamp model plus PI trim on the load
// cell, conditional-integration anti-windup, and a hard ceiling that the command can never
// be driven past (the ceiling is below the seedling's damage threshold; config checks it).

namespace planter {

struct ClampLoopConfig {
  double setpoint_N = 90.0;
  double ceiling_N = 120.0;
  double ramp_N_per_s = 60.0;  // set-point ramp at start
  double kp_mm_per_N = 0.01;
  double ki_mm_per_Ns = 0.08;
  double position_min_mm = 0.0;
  double position_max_mm = 12.0;
  double release_position_mm = 0.0;  // roller position when not clamping
  // Nominal clamp model used for feed-forward and the ceiling guard: F = k (x - x0)^n.
  double model_k_N = 14.85;
  double model_x0_mm = 2.0;
  double model_n = 1.3;
};

class ClampForceLoop {
 public:
  explicit ClampForceLoop(const ClampLoopConfig& config) : cfg_(config) {}

  void reset();
  // Returns the roller position command in mm. `enabled` false -> release position.
  double update(double force_measured_N, double dt_s, bool enabled);

  [[nodiscard]] double setpoint_N() const { return ramped_setpoint_N_; }
  // The force to clamp at (an increase ramps, a decrease is taken at once).
  void set_target_N(double target_N) { cfg_.setpoint_N = target_N; }
  [[nodiscard]] double target_N() const { return cfg_.setpoint_N; }
  [[nodiscard]] double trim_mm() const { return integral_mm_; }
  [[nodiscard]] bool ceiling_active() const { return ceiling_active_; }
  // Position at which the nominal model gives `force_N`.
  [[nodiscard]] double model_position_mm(double force_N) const;

 private:
  ClampLoopConfig cfg_;
  double ramped_setpoint_N_ = 0.0;
  double integral_mm_ = 0.0;
  bool ceiling_active_ = false;
};

}  // namespace planter
