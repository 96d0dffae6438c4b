#pragma once
// Little-endian 32-bit fields in CANopen payloads (SDO data and abort codes, LSS identities).
#include <cstdint>

namespace planter::canopen {

constexpr std::uint32_t read_le_u32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
         (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

constexpr void write_le_u32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}

}  // namespace planter::canopen
