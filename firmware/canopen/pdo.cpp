#include "firmware/canopen/pdo.h"

namespace planter::canopen {

int PdoMapping::total_bits() const {
  int bits = 0;
  for (std::size_t i = 0; i < count && i < kMaxEntries; ++i) bits += entries[i].bits;
  return bits;
}

bool PdoMapping::valid() const {
  if (count > kMaxEntries) return false;
  for (std::uint8_t i = 0; i < count; ++i) {
    const auto b = entries[i].bits;
    if (b != 8 && b != 16 && b != 32) return false;
  }
  return total_bits() <= 64;
}

std::uint8_t pdo_pack(const PdoMapping& mapping, const std::uint64_t* values, std::uint8_t* data) {
  if (!mapping.valid()) return 0;
  int byte = 0;
  for (std::uint8_t i = 0; i < mapping.count; ++i) {
    const int n = mapping.entries[i].bits / 8;
    for (int k = 0; k < n; ++k) data[byte++] = static_cast<std::uint8_t>(values[i] >> (8 * k));
  }
  return static_cast<std::uint8_t>(byte);
}

bool pdo_unpack(const PdoMapping& mapping, const std::uint8_t* data, std::uint8_t dlc,
                std::uint64_t* values) {
  if (!mapping.valid() || mapping.total_bits() > 8 * dlc) return false;
  int byte = 0;
  for (std::uint8_t i = 0; i < mapping.count; ++i) {
    const int n = mapping.entries[i].bits / 8;
    std::uint64_t v = 0;
    for (int k = 0; k < n; ++k) v |= static_cast<std::uint64_t>(data[byte++]) << (8 * k);
    values[i] = v;
  }
  return true;
}

}  // namespace planter::canopen
