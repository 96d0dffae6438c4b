#pragma once
// The controller's part of a recording row (PRODUCT.md format), shared by planterd and the
// simulator so that a field log and a simulated one have the same columns and precision.
#include <cstddef>

#include "firmware/controller/telemetry.h"

namespace planter::config {

// Header of the controller columns, without a trailing newline.
inline constexpr const char* kControllerColumns =
    "t,wheel_counts,v_wheel,omega_cmd,omega,disc_angle,disc_torque,sigma,clamp_force_cmd,"
    "clamp_pos_mm,clamp_force,depth_cmd_mm,depth_mm,depth_force,state";

// Writes the controller columns of one row (no newline) into out; returns the length, or a
// value >= size when it did not fit. No allocation.
int format_controller_columns(char* out, std::size_t size, double t_s, const Telemetry& c);

}  // namespace planter::config
