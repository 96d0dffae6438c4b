#pragma once
// CiA 309-3 data types: b, i8..i64, u8..u64, x8..x64 (unsigned, shown in hex), r32, r64,
// vs (visible string), os (octet string, hex), d (domain, hex). Text <-> little-endian bytes.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace planter::cantool {

enum class ValueKind : std::uint8_t { kBool, kSigned, kUnsigned, kHex, kReal, kString, kOctets };

struct ValueType {
  ValueKind kind = ValueKind::kUnsigned;
  std::uint8_t bytes = 4;  // 0 for strings and octets (any length)
  std::string_view name = "u32";
};

// nullopt for an unknown type name.
std::optional<ValueType> parse_value_type(std::string_view name);
// The type names, for messages: "b, i8, i16, ...".
const char* value_type_names();

// Encodes text as the type; on failure returns nullopt and sets `why`.
std::optional<std::vector<std::uint8_t>> encode_value(const ValueType& type, std::string_view text,
                                                      std::string& why);
// Formats bytes as the type (a short read is shown as what arrived).
std::string format_value(const ValueType& type, const std::vector<std::uint8_t>& bytes);
// Integer text: decimal, 0x hex, optional sign. nullopt when not a number.
std::optional<std::int64_t> parse_integer(std::string_view text);

}  // namespace planter::cantool
