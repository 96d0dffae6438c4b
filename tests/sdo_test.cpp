#include <gtest/gtest.h>

#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/sdo_client.h"
#include "sim/devices/sdo_server.h"
#include "tests/frame_script.h"

using namespace planter;
using namespace planter::canopen;
using test::expect_frame;
using test::frame;

struct SdoTest : ::testing::Test {
  hal::sim::VirtualCanBus bus;
  hal::sim::VirtualCanEndpoint& master = bus.add_endpoint();
  hal::sim::VirtualCanEndpoint& peer = bus.add_endpoint();
  SdoClient client{5, 50'000'000};
  std::array<std::uint8_t, 32> buffer{};
  void reply(std::vector<std::uint8_t> bytes) {
    hal::CanFrame f;
    peer.send(frame(0x585, std::move(bytes)));
    ASSERT_TRUE(master.receive(f));
    EXPECT_TRUE(client.on_frame(f, 1000, master));
  }
};

TEST_F(SdoTest, ExpeditedUpload) {
  ASSERT_TRUE(client.start_read(0x1000, 0, buffer, 0, master));
  expect_frame(peer, 0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  reply({0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0x02, 0x00});
  EXPECT_EQ(client.status(), SdoStatus::kDone);
  EXPECT_EQ(client.value(), 0x00020192u);
}

TEST_F(SdoTest, ExpeditedUploadAcceptsShortFrame) {
  ASSERT_TRUE(client.start_read(0x1017, 0, buffer, 0, master));
  expect_frame(peer, 0x605, {0x40, 0x17, 0x10, 0x00, 0, 0, 0, 0});
  reply({0x4B, 0x17, 0x10, 0x00, 0x64, 0x00});  // DLC 6: two data bytes
  EXPECT_EQ(client.status(), SdoStatus::kDone);
  EXPECT_EQ(client.bytes_read(), 2u);
  EXPECT_EQ(client.value(), 100u);
}

TEST_F(SdoTest, SegmentedUploadWithToggle) {
  ASSERT_TRUE(client.start_read(0x1008, 0, buffer, 0, master));
  expect_frame(peer, 0x605, {0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0});
  reply({0x41, 0x08, 0x10, 0x00, 10, 0, 0, 0});
  expect_frame(peer, 0x605, {0x60, 0, 0, 0, 0, 0, 0, 0});
  reply({0x00, 'p', 'l', 'a', 'n', 't', 'e', 'r'});
  expect_frame(peer, 0x605, {0x70, 0, 0, 0, 0, 0, 0, 0});
  reply({0x10 | (4 << 1) | 1, '-', 'd', 'i', 0, 0, 0, 0});
  EXPECT_EQ(client.status(), SdoStatus::kDone);
  EXPECT_EQ(std::string(buffer.begin(), buffer.begin() + 10), "planter-di");
}

TEST_F(SdoTest, WrongToggleAborts) {
  ASSERT_TRUE(client.start_read(0x1008, 0, buffer, 0, master));
  expect_frame(peer, 0x605, {0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0});
  reply({0x41, 0x08, 0x10, 0x00, 10, 0, 0, 0});
  expect_frame(peer, 0x605, {0x60, 0, 0, 0, 0, 0, 0, 0});
  reply({0x10, 'x', 'x', 'x', 'x', 'x', 'x', 'x'});  // toggle set on the first segment
  EXPECT_EQ(client.status(), SdoStatus::kAborted);
  EXPECT_EQ(client.abort_code(), abort_code::kToggleBit);
  expect_frame(peer, 0x605, {0x80, 0x08, 0x10, 0x00, 0x00, 0x00, 0x03, 0x05});
}

TEST_F(SdoTest, ExpeditedDownloadAndServerAbort) {
  ASSERT_TRUE(client.start_write_u32(0x1017, 0, 100, 2, 0, master));
  expect_frame(peer, 0x605, {0x2B, 0x17, 0x10, 0x00, 100, 0, 0, 0});
  reply({0x60, 0x17, 0x10, 0x00, 0, 0, 0, 0});
  EXPECT_EQ(client.status(), SdoStatus::kDone);
  client.reset();
  ASSERT_TRUE(client.start_write_u32(0x1000, 0, 1, 4, 0, master));
  expect_frame(peer, 0x605, {0x23, 0x00, 0x10, 0x00, 1, 0, 0, 0});
  reply({0x80, 0x00, 0x10, 0x00, 0x02, 0x00, 0x01, 0x06});
  EXPECT_EQ(client.status(), SdoStatus::kAborted);
  EXPECT_EQ(client.abort_code(), abort_code::kReadOnly);
  EXPECT_STREQ(abort_code_text(client.abort_code()), "attempt to write a read-only object");
}

TEST_F(SdoTest, TimeoutSendsAbort) {
  ASSERT_TRUE(client.start_read(0x1000, 0, buffer, 0, master));
  expect_frame(peer, 0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  client.poll(49'000'000, master);
  EXPECT_EQ(client.status(), SdoStatus::kBusy);
  client.poll(50'000'000, master);
  EXPECT_EQ(client.status(), SdoStatus::kTimedOut);
  expect_frame(peer, 0x605, {0x80, 0x00, 0x10, 0x00, 0x00, 0x00, 0x04, 0x05});
}

TEST_F(SdoTest, GarbageResponseAbortsCleanly) {
  ASSERT_TRUE(client.start_read(0x1000, 0, buffer, 0, master));
  hal::CanFrame f;
  ASSERT_TRUE(peer.receive(f));
  reply({0x60, 0x00, 0x10, 0x00, 0, 0, 0, 0});  // a download response to an upload
  EXPECT_EQ(client.status(), SdoStatus::kAborted);
  EXPECT_EQ(client.abort_code(), abort_code::kBadCommand);
}

// The client against the server: every path through both, segmented in both directions.
TEST(SdoClientServer, RoundTrips) {
  hal::sim::VirtualCanBus bus;
  auto& master = bus.add_endpoint();
  auto& device = bus.add_endpoint();
  ObjectDictionary od;
  od.add(0x1017, 0, 2, Access::kReadWrite, 0);
  od.add(0x1000, 0, 4, Access::kConst, 0x192);
  od.add_string(0x1008, 0, "sim disc drive");
  od.find(0x1008, 0)->text.reserve(32);
  od.find(0x1008, 0)->access = Access::kReadWrite;
  SdoServer server(7, od);
  SdoClient client(7, 100'000'000);
  auto pump = [&] {
    hal::CanFrame f;
    for (int i = 0; i < 20 && client.status() == SdoStatus::kBusy; ++i) {
      while (device.receive(f)) server.on_frame(f, device);
      while (master.receive(f)) client.on_frame(f, 0, master);
    }
  };
  std::array<std::uint8_t, 32> buf{};
  ASSERT_TRUE(client.start_read(0x1008, 0, buf, 0, master));
  pump();
  ASSERT_EQ(client.status(), SdoStatus::kDone);
  EXPECT_EQ(std::string(buf.begin(), buf.begin() + client.bytes_read()), "sim disc drive");
  client.reset();
  const std::string name = "roller clamp actuator";
  ASSERT_TRUE(client.start_write(
      0x1008, 0, std::span(reinterpret_cast<const std::uint8_t*>(name.data()), name.size()), 0,
      master));
  pump();
  ASSERT_EQ(client.status(), SdoStatus::kDone);
  EXPECT_EQ(od.find(0x1008, 0)->text, name);
  client.reset();
  ASSERT_TRUE(client.start_write_u32(0x1017, 0, 250, 2, 0, master));
  pump();
  EXPECT_EQ(od.get(0x1017, 0), 250u);
  client.reset();
  ASSERT_TRUE(client.start_read(0x2000, 0, buf, 0, master));
  pump();
  EXPECT_EQ(client.status(), SdoStatus::kAborted);
  EXPECT_EQ(client.abort_code(), abort_code::kNoObject);
  client.reset();
  ASSERT_TRUE(client.start_write_u32(0x1017, 0, 1, 4, 0, master));  // wrong length
  pump();
  EXPECT_EQ(client.abort_code(), abort_code::kLength);
}
