#pragma once
// The first bytes every SDO frame shares (CiA 301 7.2.4.3): the command byte, the multiplexer
// (index, little-endian, then sub-index), and an abort's code. Both sides build them here: the
// controller's SdoClient and the simulated nodes' SdoServer.
#include <array>
#include <cstdint>

#include "firmware/canopen/le_bytes.h"

namespace planter::canopen {

constexpr std::array<std::uint8_t, 8> sdo_mux_payload(std::uint8_t command, std::uint16_t index,
                                                      std::uint8_t sub) {
  return {command,
          static_cast<std::uint8_t>(index & 0xFF),
          static_cast<std::uint8_t>(index >> 8),
          sub,
          0,
          0,
          0,
          0};
}

constexpr std::array<std::uint8_t, 8> sdo_abort_payload(std::uint16_t index, std::uint8_t sub,
                                                        std::uint32_t code) {
  std::array<std::uint8_t, 8> p = sdo_mux_payload(0x80, index, sub);
  write_le_u32(p.data() + 4, code);
  return p;
}

}  // namespace planter::canopen
