#include "sim/hil/can_bridge.h"

namespace planter::sim {

void CanBridge::inbound() {
  hal::CanFrame frame;
  while (socket_.receive(frame)) {
    if (endpoint_.send(frame))
      ++in_;
    else
      ++lost_;
  }
}

void CanBridge::outbound() {
  hal::CanFrame frame;
  while (endpoint_.receive(frame)) {
    if (socket_.send(frame))
      ++out_;
    else
      ++lost_;
  }
}

}  // namespace planter::sim
