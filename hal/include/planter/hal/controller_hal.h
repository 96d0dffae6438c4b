#pragma once
// Everything the controller touches, handed in through its constructor (no global HAL object).
#include "planter/hal/can_bus.h"
#include "planter/hal/gnss.h"
#include "planter/hal/gpio.h"
#include "planter/hal/tick_probe.h"

namespace planter::hal {

struct ControllerHal {
  CanBus& can;
  GpioEdgeSource& edges;  // encoder A/B and the seedling photo-eye (edge_line::), in time order
  DigitalInput& estop;
  DigitalOutput& status_lamp;
  TickProbe* tick_probe = nullptr;  // optional: told when each phase of a tick ends
  GnssSource* gnss = nullptr;       // optional: the GNSS receiver, where the board has one
};

}  // namespace planter::hal
