#pragma once
// The Linux hardware a board file names, opened and checked at start: the CAN interface and
// the GPIO chip with the encoder, photo-eye, e-stop and status lines. Throws HalError with one
// message.
#include <memory>

#include "apps/planterd/edge_latency_probe.h"
#include "config/board_config.h"
#include "hal/linux/gpiod_lines.h"
#include "hal/linux/socketcan_bus.h"
#include "planter/hal/controller_hal.h"

namespace planter::daemon {

class BoardHardware {
 public:
  explicit BoardHardware(const config::BoardConfig& board);
  hal::ControllerHal& controller_hal() { return hal_; }
  hal::linux_backend::SocketCanBus& can() { return can_; }
  EdgeLatencyProbe& edge_latency() { return probe_; }

 private:
  hal::linux_backend::SocketCanBus can_;
  hal::linux_backend::GpiodChip chip_;
  hal::linux_backend::GpiodEdgeSource edges_;  // encoder A/B and the photo-eye
  hal::linux_backend::GpiodInput estop_;
  hal::linux_backend::GpiodOutput status_;
  EdgeLatencyProbe probe_;
  std::unique_ptr<hal::GnssSource> gnss_;  // gpsd's reader, where the board has a receiver
  hal::ControllerHal hal_;
};

}  // namespace planter::daemon
