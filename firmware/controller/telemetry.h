#pragma once
// What the controller saw and commanded in its last tick, in SI units (mm where named).
#include <cstdint>

#include "firmware/supervisor/supervisor.h"

namespace planter {

struct Telemetry {
  std::int64_t time_ns = 0;
  std::int64_t wheel_counts = 0;
  double distance_m = 0.0;
  double v_wheel_mps = 0.0;
  double omega_cmd_radps = 0.0;
  double omega_radps = 0.0;
  double disc_angle_rad = 0.0;
  double disc_torque_Nm = 0.0;
  double sigma = 0.0;
  double clamp_force_cmd_N = 0.0;
  double clamp_pos_cmd_mm = 0.0;
  double clamp_pos_mm = 0.0;
  double clamp_force_N = 0.0;
  double depth_cmd_mm = 0.0;
  double depth_mm = 0.0;
  double depth_force_N = 0.0;
  SupervisorState state = SupervisorState::kBoot;
  std::uint32_t faults = 0;
  std::uint32_t overruns = 0;
  std::uint32_t encoder_invalid = 0;
  std::uint32_t unknown_frames = 0;
};

}  // namespace planter
