#pragma once
// PDO mapping and byte packing (byte-aligned entries of 8, 16 or 32 bits, little-endian).
#include <array>
#include <cstddef>
#include <cstdint>

namespace planter::canopen {

struct PdoEntry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint8_t bits = 0;
  // The 32-bit mapping value as written to 0x1600/0x1A00: index<<16 | sub<<8 | bits.
  [[nodiscard]] std::uint32_t mapping_value() const {
    return (static_cast<std::uint32_t>(index) << 16) | (static_cast<std::uint32_t>(sub) << 8) |
           bits;
  }
  static PdoEntry from_mapping_value(std::uint32_t v) {
    return {static_cast<std::uint16_t>(v >> 16), static_cast<std::uint8_t>(v >> 8),
            static_cast<std::uint8_t>(v)};
  }
};

struct PdoMapping {
  static constexpr std::size_t kMaxEntries = 8;
  std::uint8_t count = 0;
  std::array<PdoEntry, kMaxEntries> entries{};

  [[nodiscard]] int total_bits() const;
  // True when every entry is 8/16/32 bits and the total fits 64 bits.
  [[nodiscard]] bool valid() const;
};

// The payload of one classic CAN frame: a mapping never packs more than this.
constexpr std::size_t kPdoMaxBytes = 8;

// values[i] is the raw value of entries[i]; data holds kPdoMaxBytes. Returns the DLC, or 0 with
// nothing written when the mapping is not valid() (a mapping taken from the bus or an SDO write
// can claim any length: it must never write past the frame).
std::uint8_t pdo_pack(const PdoMapping& mapping, const std::uint64_t* values, std::uint8_t* data);
// False (and nothing written) when the mapping is not valid() or the frame is shorter than it.
bool pdo_unpack(const PdoMapping& mapping, const std::uint8_t* data, std::uint8_t dlc,
                std::uint64_t* values);

// Sign-extends a raw value of `bits` bits.
constexpr std::int64_t sign_extend(std::uint64_t raw, unsigned bits) {
  if (bits == 0 || bits >= 64) return static_cast<std::int64_t>(raw);
  const std::uint64_t sign = 1ull << (bits - 1);
  const std::uint64_t v = raw & ((1ull << bits) - 1);
  return static_cast<std::int64_t>((v ^ sign) - sign);
}

}  // namespace planter::canopen
