#pragma once
// The controller's part of a recording row (PRODUCT.md format), shared by planterd and the
// simulator so that a field log and a simulated one have the same columns and precision. Both
// the header and the row come from the signal table (firmware/io/signal_table.h).
#include <cstddef>
#include <string>

#include "firmware/controller/telemetry.h"

namespace planter::config {

// Header of the controller columns, without a trailing newline.
std::string controller_columns();

// Writes the controller columns of one row (no newline) into out; returns the length, or a
// value >= size when it did not fit. No allocation.
int format_controller_columns(char* out, std::size_t size, double t_s, const Telemetry& c);

}  // namespace planter::config
