// The I/O layer times what it reads from the frame's arrival where the bus knows it (SocketCAN's
// kernel stamp), not from the tick that reads it: a late tick must not make a node look late.
#include <gtest/gtest.h>

#include "config/board_config.h"
#include "firmware/canopen/cob_id.h"
#include "firmware/controller/control_cycle.h"
#include "hal/sim/sim_gpio.h"
#include "hal/sim/virtual_can_bus.h"

using namespace planter;

namespace {

struct Rig {
  Rig()
      : board(config::load_board(std::string(PLANTER_SOURCE_DIR) + "/boards/host-sim/board.toml")) {
  }
  config::BoardConfig board;
  hal::sim::VirtualCanBus bus;
  hal::sim::VirtualCanEndpoint& controller_end = bus.add_endpoint();
  hal::sim::VirtualCanEndpoint& node_end = bus.add_endpoint();
  hal::sim::SimEdgeSource encoder;
  hal::sim::SimDigitalInput estop;
  hal::sim::SimDigitalOutput lamp;
  hal::ControllerHal hal{controller_end, encoder, estop, lamp};

  void heartbeat(std::uint8_t node, std::int64_t rx_time_ns) {
    hal::CanFrame f;
    f.id = canopen::kHeartbeatBase + node;
    f.dlc = 1;
    f.data[0] = 0x05;  // operational
    f.rx_time_ns = rx_time_ns;
    node_end.send(f);
  }
};

}  // namespace

TEST(MachineIo, TimesAFrameFromItsArrival) {
  Rig rig;
  ControlCycle cycle(rig.board.controller, rig.hal);
  const std::uint8_t disc = rig.board.controller.node(NodeRole::kDiscDrive).node_id;
  rig.heartbeat(disc, 42'000'000);  // arrived at 42 ms, read by the tick at 50 ms
  cycle.tick(50'000'000, 10'000'000);
  EXPECT_EQ(cycle.node(NodeRole::kDiscDrive).heartbeat().last_ns(), 42'000'000);
  rig.heartbeat(disc, -1);  // a bus that cannot say: the tick's time
  cycle.tick(60'000'000, 10'000'000);
  EXPECT_EQ(cycle.node(NodeRole::kDiscDrive).heartbeat().last_ns(), 60'000'000);
  rig.heartbeat(disc, 90'000'000);  // a stamp from the future is not believed
  cycle.tick(70'000'000, 10'000'000);
  EXPECT_EQ(cycle.node(NodeRole::kDiscDrive).heartbeat().last_ns(), 70'000'000);
}
