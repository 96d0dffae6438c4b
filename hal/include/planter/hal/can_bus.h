#pragma once
#include "planter/hal/can_frame.h"

namespace planter::hal {

struct CanBusCounters {
  std::uint32_t tx_frames = 0;
  std::uint32_t rx_frames = 0;
  std::uint32_t tx_dropped = 0;   // refused: queue full or bus-off
  std::uint32_t rx_overflow = 0;  // lost because the receive queue was full
  std::uint32_t error_frames = 0;
  bool bus_off = false;
  bool link_up = true;           // the interface is up: false while a cable or adapter is out
  std::uint32_t link_downs = 0;  // times the interface went down since it was opened
};

// One CAN interface. Non-blocking: the control loop polls it once per tick.
class CanBus {
 public:
  virtual ~CanBus() = default;
  // Queues a frame for transmission. False when it cannot be queued (full, bus-off).
  virtual bool send(const CanFrame& frame) = 0;
  // Takes the oldest received frame. False when none is pending.
  virtual bool receive(CanFrame& frame) = 0;
  [[nodiscard]] virtual CanBusCounters counters() const = 0;
};

}  // namespace planter::hal
