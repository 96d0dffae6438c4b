#pragma once
// Furrow depth: a rate-limited set-point ramp plus integral trim on the measured depth, so a
// constant offset (actuator compliance under soil draft) is taken out. The trim is bounded by
// the actuator's travel (the machine's end stops, from its calibration), not by a constant:
// the command never asks past an end stop, and the integral stops there (back-calculation).

namespace planter {

struct DepthLoopConfig {
  double target_mm = 102.0;
  double rate_mm_per_s = 20.0;
  // The integral's crossover at 5 rad/s: ten times the 0.5 s period of the paper's field's
  // terrain at 0.45 m wavelength and 0.06 m/s (0.84 rad/s), below the actuator's 0.05 s lag
  // and the sensor's two ticks (phase margin about 65 deg; docs/control.md).
  double ki_per_s = 5.0;
  double min_mm = 0.0;
  double max_mm = 165.0;   // the opener's lower end stop (the machine's; calibration replaces it)
  double raised_mm = 0.0;  // opener position out of the ground
};

// What the loop saw this tick, for the alarms (firmware/supervisor/loop_alarms.h).
struct DepthStatus {
  bool settled = false;      // the ramp has reached the target
  bool at_end_stop = false;  // the command is held at an end stop
  double error_mm = 0;       // target - measured
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
  [[nodiscard]] const DepthStatus& status() const { return status_; }

 private:
  DepthLoopConfig cfg_;
  double ramped_mm_ = 0.0;
  double trim_mm_ = 0.0;
  DepthStatus status_;
};

}  // namespace planter
