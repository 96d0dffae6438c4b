#pragma once
// Furrow depth: a rate-limited set-point ramp plus integral trim on the measured depth, so a
// constant offset (actuator compliance under soil draft) is taken out.

namespace planter {

struct DepthLoopConfig {
  double target_mm = 102.0;
  double rate_mm_per_s = 20.0;
  double ki_per_s = 0.5;
  double trim_max_mm = 15.0;
  double min_mm = 0.0;
  double max_mm = 170.0;
  double raised_mm = 0.0;  // opener position out of the ground
};

class FurrowDepthLoop {
 public:
  explicit FurrowDepthLoop(const DepthLoopConfig& config) : cfg_(config) {}

  void reset(double measured_depth_mm);
  // Returns the depth actuator position command in mm; `engaged` false ramps up to raised.
  double update(double measured_depth_mm, double dt_s, bool engaged);
  [[nodiscard]] double setpoint_mm() const { return ramped_mm_; }
  // The depth to plant at; the opener ramps to a new one at the rate limit.
  void set_target_mm(double target_mm) { cfg_.target_mm = target_mm; }
  [[nodiscard]] double target_mm() const { return cfg_.target_mm; }

 private:
  DepthLoopConfig cfg_;
  double ramped_mm_ = 0.0;
  double trim_mm_ = 0.0;
};

}  // namespace planter
