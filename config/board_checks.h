#pragma once
// Checks of a board that every key's own range cannot make: the arithmetic the values feed.
// A value in range can still wrap a 32-bit object, round every command to zero, or ask the bus
// for more bits than it carries.
#include <string>

#include "firmware/controller/controller_config.h"

namespace planter::config {

class TomlSection;

// The bus load the board's configuration plans: SYNC, every mapped PDO once per SYNC period
// and the heartbeats, in bits with worst-case stuffing (hal::can_frame_bits), as a percentage of
// the bit rate.
[[nodiscard]] double planned_bus_load_pct(const ControllerConfig& c);

// Refuses (ConfigError naming the node's key) a counts_per_unit whose largest value overflows
// an object the node maps, or whose one count is coarser than the loop can work with.
void check_node_scaling(TomlSection& node, const NodeConfig& n, const ControllerConfig& c);

}  // namespace planter::config
