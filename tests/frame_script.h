#pragma once
// Frame-script helpers: a bus endpoint pair where the test plays the other side.
#include <gtest/gtest.h>

#include <vector>

#include "hal/sim/virtual_can_bus.h"

namespace planter::test {

inline hal::CanFrame frame(std::uint16_t id, std::vector<std::uint8_t> bytes) {
  hal::CanFrame f{};
  f.id = id;
  f.dlc = static_cast<std::uint8_t>(bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) f.data[i] = bytes[i];
  return f;
}

inline void expect_frame(hal::CanBus& peer, std::uint16_t id, std::vector<std::uint8_t> bytes) {
  hal::CanFrame f;
  ASSERT_TRUE(peer.receive(f)) << "expected a frame 0x" << std::hex << id;
  EXPECT_EQ(f.cob_id(), id);
  ASSERT_EQ(f.dlc, bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) EXPECT_EQ(f.data[i], bytes[i]) << "byte " << i;
}

}  // namespace planter::test
