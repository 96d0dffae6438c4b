#pragma once
// A classic CAN 2.0 frame as the firmware sees it, independent of SocketCAN's struct.
#include <array>
#include <cstdint>

namespace planter::hal {

struct CanFrame {
  static constexpr std::uint32_t kExtendedFlag = 0x80000000u;  // same bit as SocketCAN's EFF
  static constexpr std::uint32_t kRemoteFlag = 0x40000000u;
  static constexpr std::uint32_t kErrorFlag = 0x20000000u;

  std::uint32_t id = 0;  // 11-bit identifier, plus the flags above
  std::uint8_t dlc = 0;
  std::array<std::uint8_t, 8> data{};
  // When the frame arrived, on the controller's monotonic clock (receive() sets it where the
  // backend knows it, as AP_HAL's CAN receive does); -1 when unknown. Ignored by send().
  std::int64_t rx_time_ns = -1;

  [[nodiscard]] std::uint16_t cob_id() const { return static_cast<std::uint16_t>(id & 0x7FFu); }
  [[nodiscard]] bool is_standard_data() const {
    return (id & (kExtendedFlag | kRemoteFlag | kErrorFlag)) == 0;
  }
};

// Bits on the wire of a standard data frame, worst-case bit stuffing included; used for bus load.
constexpr int can_frame_bits(int dlc) {
  const int unstuffed = 34 + 8 * dlc;           // SOF..CRC: the part that is stuffed
  return unstuffed + (unstuffed - 1) / 4 + 13;  // + stuff bits + CRC delim, ACK, EOF, IFS
}

}  // namespace planter::hal
