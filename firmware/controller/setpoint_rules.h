#pragma once
// The operator's set-points and what may be asked of them: one rule for the machine file and
// for every command at run time (the console), so a value the file would refuse is refused
// live, and the other way round.
#include "firmware/controller/controller_config.h"

namespace planter {

struct SetpointRange {
  double min = 0.0;
  double max = 0.0;
  bool max_exclusive = false;  // the value must stay below max
  [[nodiscard]] bool allows(double v) const {
    return v >= min && (max_exclusive ? v < max : v <= max);  // false for NaN
  }
};

// The furrow depths the paper tested (its Box-Behnken design spans 40-160 mm); the machine file
// may allow less (the actuator's travel, depth_max_mm).
constexpr SetpointRange kDepthFileRangeMm{40.0, 160.0, false};
// The clamp force the file accepts before the ceiling is considered.
constexpr SetpointRange kClampForceFileRangeN{0.0, 200.0, false};

// What this machine allows: the file's range within the actuator's travel.
inline SetpointRange depth_range_mm(const ControllerConfig& c) {
  return {kDepthFileRangeMm.min < c.depth.min_mm ? c.depth.min_mm : kDepthFileRangeMm.min,
          kDepthFileRangeMm.max > c.depth.max_mm ? c.depth.max_mm : kDepthFileRangeMm.max, false};
}
// Below the clamp ceiling, which is below the weakest measured seedling.
inline SetpointRange clamp_force_range_N(const ControllerConfig& c) {
  return {
      kClampForceFileRangeN.min,
      kClampForceFileRangeN.max < c.clamp.ceiling_N ? kClampForceFileRangeN.max : c.clamp.ceiling_N,
      kClampForceFileRangeN.max >= c.clamp.ceiling_N};
}

}  // namespace planter
