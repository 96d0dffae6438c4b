#include "hal/sim/virtual_can_bus.h"

#include <gtest/gtest.h>

#include "tests/frame_script.h"

using namespace planter;

TEST(VirtualCanBus, DeliversToOthersInOrder) {
  hal::sim::VirtualCanBus bus;
  auto& a = bus.add_endpoint();
  auto& b = bus.add_endpoint();
  auto& c = bus.add_endpoint();
  a.send(test::frame(0x181, {1}));
  a.send(test::frame(0x182, {2}));
  hal::CanFrame f;
  EXPECT_FALSE(a.receive(f));
  test::expect_frame(b, 0x181, {1});
  test::expect_frame(b, 0x182, {2});
  test::expect_frame(c, 0x181, {1});
}

TEST(VirtualCanBus, InjectedFaults) {
  hal::sim::VirtualCanBus bus;
  auto& a = bus.add_endpoint(2);
  auto& b = bus.add_endpoint(2);
  hal::CanFrame f;
  bus.drop_next_frames(1);
  a.send(test::frame(0x100, {}));
  EXPECT_FALSE(b.receive(f));
  EXPECT_EQ(bus.frames_dropped(), 1u);
  for (int i = 0; i < 3; ++i) a.send(test::frame(0x100, {}));
  EXPECT_EQ(b.counters().rx_overflow, 1u);
  while (b.receive(f)) {
  }
  bus.set_bus_off(true);
  EXPECT_FALSE(a.send(test::frame(0x100, {})));
  EXPECT_TRUE(a.counters().bus_off);
  bus.set_bus_off(false);
  b.set_unplugged(true);
  a.send(test::frame(0x100, {}));
  EXPECT_FALSE(b.receive(f));
  bus.inject_error_frame();
  EXPECT_TRUE(a.receive(f));
  EXPECT_FALSE(f.is_standard_data());
  EXPECT_EQ(a.counters().error_frames, 1u);
}

TEST(VirtualCanBus, FrameBitsForBusLoad) {
  EXPECT_EQ(hal::can_frame_bits(0), 34 + 8 + 13);
  EXPECT_GT(hal::can_frame_bits(8), hal::can_frame_bits(2));
  EXPECT_LE(hal::can_frame_bits(8), 135);
}
