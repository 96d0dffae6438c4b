// The simulated nodes refuse over SDO what CiA 301 and 402 require a device to refuse, and a
// PDO mapping from the bus can never make a TPDO write past its 8-byte frame.
#include <gtest/gtest.h>

#include "firmware/canopen/cia402.h"
#include "firmware/canopen/sdo_client.h"
#include "hal/sim/virtual_can_bus.h"
#include "sim/devices/cia402_drive_device.h"

namespace planter {
namespace {

namespace ac = canopen::abort_code;
using canopen::SdoClient;
using canopen::SdoStatus;

class DeviceRules : public ::testing::Test {
 protected:
  hal::sim::VirtualCanBus bus;
  hal::sim::VirtualCanEndpoint& master = bus.add_endpoint();
  hal::sim::VirtualCanEndpoint& node_side = bus.add_endpoint();
  sim::Cia402DriveDevice drive{{3, 0x20192, 0x1234, 0x5678, 1, 1, "disc drive"}, node_side};

  void SetUp() override {
    drive.power_on(0);
    drain();
  }
  void drain() {
    hal::CanFrame f;
    while (master.receive(f)) {
    }
  }
  // Writes `value` of `size` bytes over SDO; returns 0 or the abort code.
  std::uint32_t write(std::uint16_t index, std::uint8_t sub, std::uint32_t value,
                      std::size_t size) {
    SdoClient client(3, 100'000'000);
    EXPECT_TRUE(client.start_write_u32(index, sub, value, size, 0, master));
    hal::CanFrame f;
    for (int i = 0; i < 10 && client.status() == SdoStatus::kBusy; ++i) {
      drive.process(0);
      while (master.receive(f)) client.on_frame(f, 0, master);
    }
    EXPECT_NE(client.status(), SdoStatus::kBusy);
    return client.status() == SdoStatus::kDone ? 0 : client.abort_code();
  }
  void nmt(canopen::NmtCommand c) {
    hal::CanFrame f{};
    f.id = canopen::kNmtCobId;
    f.dlc = 2;
    f.data[0] = static_cast<std::uint8_t>(c);
    f.data[1] = 3;
    master.send(f);
    drive.process(0);
  }
};

TEST_F(DeviceRules, OversizedMappingIsRefusedAndNoFrameOverflows) {
  // The reproduction: 8 entries of 255 bits into 0x1A00, then start and SYNC.
  ASSERT_EQ(write(0x1A00, 0, 0, 1), 0u);
  for (std::uint8_t s = 1; s <= 8; ++s)
    EXPECT_EQ(write(0x1A00, s, (0x6064u << 16) | 0xFF, 4), ac::kCannotMap) << int(s);
  // Entries the node can map, but 3 x 32 bits = 96 > 64: the count is refused.
  for (std::uint8_t s = 1; s <= 3; ++s) EXPECT_EQ(write(0x1A00, s, 0x60640020, 4), 0u);
  EXPECT_EQ(write(0x1A00, 0, 3, 1), ac::kMapLength);
  EXPECT_EQ(write(0x1A00, 0, 9, 1), ac::kMapLength);  // beyond the 8 entries
  EXPECT_EQ(write(0x1A00, 0, 2, 1), 0u);
  EXPECT_EQ(write(0x1800, 1, 0x183, 4), 0u);  // valid now
  EXPECT_EQ(write(0x1800, 2, 1, 1), 0u);
  nmt(canopen::NmtCommand::kStart);
  hal::CanFrame sync{};
  sync.id = canopen::kSyncCobId;
  master.send(sync);
  drive.process(0);
  hal::CanFrame f;
  bool tpdo = false;
  while (master.receive(f)) {
    if (f.id == 0x183) {
      tpdo = true;
      EXPECT_EQ(f.dlc, 8);
    }
  }
  EXPECT_TRUE(tpdo);
}

TEST_F(DeviceRules, MappingChangesOnlyWhileThePdoIsInvalidAndEmpty) {
  ASSERT_EQ(write(0x1A00, 0, 0, 1), 0u);
  ASSERT_EQ(write(0x1A00, 1, 0x60410010, 4), 0u);
  ASSERT_EQ(write(0x1A00, 0, 1, 1), 0u);
  EXPECT_EQ(write(0x1A00, 1, 0x60640020, 4), ac::kUnsupportedAccess);  // sub 0 is not 0
  ASSERT_EQ(write(0x1800, 1, 0x183, 4), 0u);
  EXPECT_EQ(write(0x1A00, 0, 0, 1), ac::kUnsupportedAccess);  // the PDO is valid
  EXPECT_EQ(write(0x1800, 1, 0x184, 4), ac::kValueRange);     // COB-ID of a valid PDO
  EXPECT_EQ(write(0x1800, 2, 245, 1), ac::kValueRange);       // reserved transmission type
  // Objects the node does not have, or cannot map that way.
  ASSERT_EQ(write(0x1800, 1, 0x80000183, 4), 0u);
  ASSERT_EQ(write(0x1A00, 0, 0, 1), 0u);
  EXPECT_EQ(write(0x1A00, 1, 0x7777'0010, 4), ac::kNoObject);
  EXPECT_EQ(write(0x1A00, 1, 0x6064'0010, 4), ac::kCannotMap);  // 16 bits of a 32-bit object
  EXPECT_EQ(write(0x1600, 1, 0x6041'0010, 4), ac::kCannotMap);  // a read-only object received
}

TEST_F(DeviceRules, StoreSignatureModesAndErrorHistory) {
  EXPECT_EQ(write(0x1010, 1, 0x12345678, 4), ac::kCannotStore);
  EXPECT_EQ(write(0x1010, 1, 0x65766173, 4), 0u);  // "save"
  EXPECT_EQ(write(canopen::cia402::kModesOfOperation, 0, 99, 1), ac::kValueRange);
  EXPECT_EQ(write(canopen::cia402::kModesOfOperation, 0, 2, 1), ac::kValueRange);  // unsupported
  EXPECT_EQ(write(canopen::cia402::kModesOfOperation, 0, 3, 1), 0u);
  EXPECT_EQ(write(canopen::cia402::kModesOfOperation, 0, 6, 1), 0u);
  EXPECT_EQ(write(0x1003, 0, 5, 1), ac::kValueRange);
  EXPECT_EQ(write(0x1003, 0, 0, 1), 0u);
}

TEST(PdoPack, InvalidMappingPacksNothing) {
  canopen::PdoMapping m;
  m.count = 8;
  for (auto& e : m.entries) e = {0x6064, 0, 255};
  std::array<std::uint8_t, 8> data{};
  const std::uint64_t values[8]{};
  EXPECT_EQ(canopen::pdo_pack(m, values, data.data()), 0);
  std::uint64_t out[8]{};
  EXPECT_FALSE(canopen::pdo_unpack(m, data.data(), 8, out));
  m.count = 200;  // a count beyond the entries is invalid, not read past the array
  EXPECT_FALSE(m.valid());
  EXPECT_EQ(canopen::pdo_pack(m, values, data.data()), 0);
}

}  // namespace
}  // namespace planter
