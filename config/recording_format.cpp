#include "config/recording_format.h"

#include <cstdio>

namespace planter::config {

int format_controller_columns(char* out, std::size_t size, double t_s, const Telemetry& c) {
  return std::snprintf(
      out, size, "%.3f,%lld,%.5f,%.5f,%.5f,%.5f,%.4f,%.4f,%.2f,%.4f,%.2f,%.3f,%.3f,%.2f,%s", t_s,
      static_cast<long long>(c.wheel_counts), c.v_wheel_mps, c.omega_cmd_radps, c.omega_radps,
      c.disc_angle_rad, c.disc_torque_Nm, c.sigma, c.clamp_force_cmd_N, c.clamp_pos_mm,
      c.clamp_force_N, c.depth_cmd_mm, c.depth_mm, c.depth_force_N, supervisor_state_name(c.state));
}

}  // namespace planter::config
