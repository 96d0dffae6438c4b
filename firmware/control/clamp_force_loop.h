#pragma once
// Roller clamp force: feed-forward through the nominal clamp model plus PI trim on the load
// cell, conditional-integration anti-windup, and a hard ceiling that the command can never
// be driven past (the ceiling is below the seedling's damage threshold; config checks it).
#include "firmware/controller/controller_config.h"

namespace planter {

class ClampForceLoop {
 public:
  explicit ClampForceLoop(const ClampLoopConfig& config) : cfg_(config) {}

  void reset();
  // Returns the roller position command in mm. `enabled` false -> release position.
  double update(double force_measured_N, double dt_s, bool enabled);

  [[nodiscard]] double setpoint_N() const { return ramped_setpoint_N_; }
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
