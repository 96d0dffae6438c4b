// Fuzz target: one CAN frame from untrusted bytes through every decoder that meets frames from
// the bus: the tool's decoder (with the board's PDO maps), the firmware's SDO client, the
// controller's node link, the LSS slave and PDO unpacking. Nothing may crash, read out of
// bounds or hang.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "apps/planter-can/frame_decoder.h"
#include "config/board_config.h"
#include "firmware/canopen/lss.h"
#include "firmware/canopen/sdo_client.h"
#include "firmware/io/node_link.h"

namespace {

class NullBus final : public planter::hal::CanBus {
 public:
  bool send(const planter::hal::CanFrame&) override { return true; }
  bool receive(planter::hal::CanFrame&) override { return false; }
  [[nodiscard]] planter::hal::CanBusCounters counters() const override { return {}; }
};

const planter::config::BoardConfig& board() {
  static const planter::config::BoardConfig b =
      planter::config::load_board(PLANTER_SOURCE_DIR "/boards/host-sim/board.toml");
  return b;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace planter;
  if (size < 5) return 0;
  hal::CanFrame f{};
  std::memcpy(&f.id, data, 4);
  f.dlc = data[4];  // may claim more than 8 bytes: decoders must not believe it
  const std::size_t n = std::min<std::size_t>(size - 5, 8);
  std::memcpy(f.data.data(), data + 5, n);

  const cantool::FrameDecoder decoder(&board().controller);
  (void)decoder.decode(f);

  NullBus bus;
  if (f.dlc > 8) f.dlc = 8;  // hal::CanBus never delivers more (SocketCAN's can_dlc <= 8)
  std::array<std::uint8_t, 16> buffer{};
  canopen::SdoClient client(static_cast<std::uint8_t>(f.id & 0x7F), 1000);
  client.start_read(0x1008, 0, buffer, 0, bus);
  client.on_frame(f, 1, bus);
  client.on_frame(f, 2, bus);  // a second one in whatever phase the first left
  NodeLink link(board().controller.node(NodeRole::kDiscDrive), board().controller.can);
  link.on_frame(f, 0, bus);
  canopen::LssSlave lss({1, 2, 3, 4}, canopen::kUnconfiguredNodeId);
  lss.on_frame(f, bus);
  return 0;
}
