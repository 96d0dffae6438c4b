#pragma once
// Everything the controller touches, handed in through its constructor (no global HAL object).
#include "planter/hal/can_bus.h"
#include "planter/hal/gpio.h"
#include "planter/hal/tick_probe.h"

namespace planter::hal {

struct ControllerHal {
  CanBus& can;
  GpioEdgeSource& encoder;  // soil-wheel quadrature encoder: line 0 = A, line 1 = B
  DigitalInput& estop;
  DigitalOutput& status_lamp;
  TickProbe* tick_probe = nullptr;  // optional: told when each phase of a tick ends
};

}  // namespace planter::hal
