#pragma once
// An in-process CAN bus: every endpoint sees every frame the others send, in order.
// Faults are injected here (drops, error frames, bus-off, an unplugged endpoint) so the
// protocol code above it can be tested against them deterministically.
#include <cstdint>
#include <memory>
#include <vector>

#include "hal/sim/fixed_ring.h"
#include "planter/hal/can_bus.h"

namespace planter::hal::sim {

class VirtualCanBus;

class VirtualCanEndpoint final : public CanBus {
 public:
  VirtualCanEndpoint(VirtualCanBus& bus, std::size_t rx_capacity, bool receive_own);
  bool send(const CanFrame& frame) override;
  bool receive(CanFrame& frame) override;
  [[nodiscard]] CanBusCounters counters() const override;

  // Unplugged: frames sent are lost and nothing is received (a node that stops answering, or
  // the controller's own cable pulled: its counters then read the link down).
  void set_unplugged(bool unplugged) {
    if (unplugged && !unplugged_) ++counters_.link_downs;
    unplugged_ = unplugged;
    counters_.link_up = !unplugged;
  }
  [[nodiscard]] bool unplugged() const { return unplugged_; }
  [[nodiscard]] std::size_t pending() const { return rx_.size(); }

 private:
  friend class VirtualCanBus;
  void deliver(const CanFrame& frame);

  VirtualCanBus& bus_;
  FixedRing<CanFrame> rx_;
  bool receive_own_;
  bool unplugged_ = false;
  CanBusCounters counters_{};
};

class VirtualCanBus {
 public:
  explicit VirtualCanBus(std::uint32_t bitrate_bps = 500000) : bitrate_bps_(bitrate_bps) {}
  // Endpoints live as long as the bus.
  VirtualCanEndpoint& add_endpoint(std::size_t rx_capacity = 256, bool receive_own = false);

  // Fault injection.
  void drop_next_frames(std::uint32_t count) { drop_next_ += count; }
  void set_drop_every_nth(std::uint32_t n) { drop_every_nth_ = n; }
  void set_bus_off(bool off) { bus_off_ = off; }
  void inject_error_frame();

  [[nodiscard]] bool bus_off() const { return bus_off_; }
  [[nodiscard]] std::uint64_t bits_transmitted() const { return bits_; }
  [[nodiscard]] std::uint64_t frames_transmitted() const { return frames_; }
  [[nodiscard]] std::uint64_t frames_dropped() const { return dropped_; }
  [[nodiscard]] std::uint32_t bitrate_bps() const { return bitrate_bps_; }

 private:
  friend class VirtualCanEndpoint;
  bool transmit(VirtualCanEndpoint& from, const CanFrame& frame);

  std::uint32_t bitrate_bps_;
  std::vector<std::unique_ptr<VirtualCanEndpoint>> endpoints_;
  std::uint32_t drop_next_ = 0;
  std::uint32_t drop_every_nth_ = 0;
  bool bus_off_ = false;
  std::uint64_t bits_ = 0;
  std::uint64_t frames_ = 0;
  std::uint64_t dropped_ = 0;
};

}  // namespace planter::hal::sim
