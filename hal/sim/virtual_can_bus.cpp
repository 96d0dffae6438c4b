#include "hal/sim/virtual_can_bus.h"

namespace planter::hal::sim {

VirtualCanEndpoint::VirtualCanEndpoint(VirtualCanBus& bus, std::size_t rx_capacity,
                                       bool receive_own)
    : bus_(bus), rx_(rx_capacity), receive_own_(receive_own) {}

bool VirtualCanEndpoint::send(const CanFrame& frame) {
  if (bus_.bus_off_) {
    ++counters_.tx_dropped;
    return false;
  }
  ++counters_.tx_frames;
  if (unplugged_) return true;  // the sender cannot tell: the frame just never arrives
  bus_.transmit(*this, frame);
  return true;
}

bool VirtualCanEndpoint::receive(CanFrame& frame) {
  if (!rx_.pop(frame)) return false;
  ++counters_.rx_frames;
  if ((frame.id & CanFrame::kErrorFlag) != 0) ++counters_.error_frames;
  return true;
}

CanBusCounters VirtualCanEndpoint::counters() const {
  CanBusCounters c = counters_;
  c.bus_off = bus_.bus_off_;
  return c;
}

void VirtualCanEndpoint::deliver(const CanFrame& frame) {
  if (unplugged_) return;
  if (!rx_.push(frame)) ++counters_.rx_overflow;
}

VirtualCanEndpoint& VirtualCanBus::add_endpoint(std::size_t rx_capacity, bool receive_own) {
  endpoints_.push_back(std::make_unique<VirtualCanEndpoint>(*this, rx_capacity, receive_own));
  return *endpoints_.back();
}

bool VirtualCanBus::transmit(VirtualCanEndpoint& from, const CanFrame& frame) {
  ++frames_;
  bits_ += static_cast<std::uint64_t>(can_frame_bits(frame.dlc));
  if (drop_next_ > 0) {
    --drop_next_;
    ++dropped_;
    return false;
  }
  if (drop_every_nth_ > 0 && frames_ % drop_every_nth_ == 0) {
    ++dropped_;
    return false;
  }
  for (auto& endpoint : endpoints_) {
    if (endpoint.get() == &from && !from.receive_own_) continue;
    endpoint->deliver(frame);
  }
  return true;
}

void VirtualCanBus::inject_error_frame() {
  CanFrame error{};
  error.id = CanFrame::kErrorFlag;
  error.dlc = 8;
  for (auto& endpoint : endpoints_) endpoint->deliver(error);
}

}  // namespace planter::hal::sim
