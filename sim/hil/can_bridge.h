#pragma once
// Joins the simulator's virtual bus to a real CAN bus: frames from the socket are sent on a
// bridge endpoint of the virtual bus (so every simulated node sees them), and frames the
// simulated nodes send are written to the socket.
#include <cstdint>

#include "hal/linux/socketcan_bus.h"
#include "hal/sim/virtual_can_bus.h"

namespace planter::sim {

class CanBridge {
 public:
  CanBridge(hal::linux_backend::SocketCanBus& socket, hal::sim::VirtualCanBus& bus)
      : socket_(socket), endpoint_(bus.add_endpoint(1024)) {}
  // Real bus -> simulated nodes.
  void inbound();
  // Simulated nodes -> real bus.
  void outbound();
  [[nodiscard]] std::uint64_t frames_in() const { return in_; }
  [[nodiscard]] std::uint64_t frames_out() const { return out_; }
  [[nodiscard]] std::uint64_t frames_lost() const { return lost_; }

 private:
  hal::linux_backend::SocketCanBus& socket_;
  hal::sim::VirtualCanEndpoint& endpoint_;
  std::uint64_t in_ = 0, out_ = 0, lost_ = 0;
};

}  // namespace planter::sim
