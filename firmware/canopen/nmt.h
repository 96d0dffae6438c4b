#pragma once
// The NMT command frame (COB-ID 0, two bytes), built in one place for the controller and the
// commissioning tool.
#include "firmware/canopen/cob_id.h"
#include "planter/hal/can_frame.h"

namespace planter::canopen {

// node_id 0 addresses every node.
constexpr hal::CanFrame nmt_frame(NmtCommand command, std::uint8_t node_id) {
  hal::CanFrame f{};
  f.id = kNmtCobId;
  f.dlc = 2;
  f.data[0] = static_cast<std::uint8_t>(command);
  f.data[1] = node_id;
  return f;
}

}  // namespace planter::canopen
