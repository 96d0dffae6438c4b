#pragma once
// Furrow depth: a rate-limited set-point ramp plus integral trim on the measured depth, so a
// constant offset (actuator compliance under soil draft) is taken out.
#include "firmware/controller/controller_config.h"

namespace planter {

class FurrowDepthLoop {
 public:
  explicit FurrowDepthLoop(const DepthLoopConfig& config) : cfg_(config) {}

  void reset(double measured_depth_mm);
  // Returns the depth actuator position command in mm; `engaged` false ramps up to raised.
  double update(double measured_depth_mm, double dt_s, bool engaged);
  [[nodiscard]] double setpoint_mm() const { return ramped_mm_; }

 private:
  DepthLoopConfig cfg_;
  double ramped_mm_ = 0.0;
  double trim_mm_ = 0.0;
};

}  // namespace planter
