#include "apps/planter-can/value_codec.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace planter::cantool {
namespace {

struct TypeRow {
  const char* name;
  ValueKind kind;
  std::uint8_t bytes;
};

constexpr std::array<TypeRow, 18> kTypes{{
    {"b", ValueKind::kBool, 1},
    {"i8", ValueKind::kSigned, 1},
    {"i16", ValueKind::kSigned, 2},
    {"i32", ValueKind::kSigned, 4},
    {"i64", ValueKind::kSigned, 8},
    {"u8", ValueKind::kUnsigned, 1},
    {"u16", ValueKind::kUnsigned, 2},
    {"u32", ValueKind::kUnsigned, 4},
    {"u64", ValueKind::kUnsigned, 8},
    {"x8", ValueKind::kHex, 1},
    {"x16", ValueKind::kHex, 2},
    {"x32", ValueKind::kHex, 4},
    {"x64", ValueKind::kHex, 8},
    {"r32", ValueKind::kReal, 4},
    {"r64", ValueKind::kReal, 8},
    {"vs", ValueKind::kString, 0},
    {"os", ValueKind::kOctets, 0},
    {"d", ValueKind::kOctets, 0},
}};

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

void put_le(std::vector<std::uint8_t>& out, std::uint64_t v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::uint64_t get_le(const std::vector<std::uint8_t>& b, std::size_t n) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < n && i < b.size(); ++i) v |= std::uint64_t{b[i]} << (8 * i);
  return v;
}

}  // namespace

std::optional<ValueType> parse_value_type(std::string_view name) {
  for (const auto& t : kTypes) {
    if (name == t.name) return ValueType{t.kind, t.bytes, t.name};
  }
  return std::nullopt;
}

const char* value_type_names() {
  return "b, i8, i16, i32, i64, u8, u16, u32, u64, x8, x16, x32, x64, r32, r64, vs, os, d";
}

std::optional<std::int64_t> parse_integer(std::string_view text) {
  bool negative = false;
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
    negative = text[0] == '-';
    text.remove_prefix(1);
  }
  int base = 10;
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    base = 16;
    text.remove_prefix(2);
  }
  if (text.empty()) return std::nullopt;
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v, base);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (negative) {
    if (v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()) + 1)
      return std::nullopt;
    return static_cast<std::int64_t>(0 - v);
  }
  return static_cast<std::int64_t>(v);  // u64 above INT64_MAX wraps; callers re-check
}

std::optional<std::vector<std::uint8_t>> encode_value(const ValueType& type, std::string_view text,
                                                      std::string& why) {
  std::vector<std::uint8_t> out;
  const unsigned bits = 8u * type.bytes;
  switch (type.kind) {
    case ValueKind::kBool: {
      if (text == "1" || text == "true") return std::vector<std::uint8_t>{1};
      if (text == "0" || text == "false") return std::vector<std::uint8_t>{0};
      why = "0, 1, true or false";
      return std::nullopt;
    }
    case ValueKind::kSigned: {
      const auto v = parse_integer(text);
      const std::int64_t lo =
          bits == 64 ? std::numeric_limits<std::int64_t>::min() : -(std::int64_t{1} << (bits - 1));
      const std::int64_t hi = bits == 64 ? std::numeric_limits<std::int64_t>::max()
                                         : (std::int64_t{1} << (bits - 1)) - 1;
      if (!v || *v < lo || *v > hi || (text.size() > 0 && text[0] != '-' && *v < 0)) {
        why = "an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
        return std::nullopt;
      }
      put_le(out, static_cast<std::uint64_t>(*v), type.bytes);
      return out;
    }
    case ValueKind::kUnsigned:
    case ValueKind::kHex: {
      if (!text.empty() && text[0] == '-') {
        why = "an unsigned integer (decimal or 0x hex)";
        return std::nullopt;
      }
      const auto v = parse_integer(text);
      const std::uint64_t max = bits == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
      if (!v || static_cast<std::uint64_t>(*v) > max) {
        why = "an unsigned integer from 0 to " + std::to_string(max);
        return std::nullopt;
      }
      put_le(out, static_cast<std::uint64_t>(*v), type.bytes);
      return out;
    }
    case ValueKind::kReal: {
      const std::string s(text);
      char* end = nullptr;
      const double d = std::strtod(s.c_str(), &end);
      if (s.empty() || end != s.c_str() + s.size()) {
        why = "a real number";
        return std::nullopt;
      }
      // A process value is finite: nan and inf would reach a device as a set-point, and
      // 1e39 would silently become +inf in 32 bits.
      const double max = type.bytes == 4 ? static_cast<double>(std::numeric_limits<float>::max())
                                         : std::numeric_limits<double>::max();
      if (!std::isfinite(d) || std::fabs(d) > max) {
        why = type.bytes == 4 ? "a finite real number within +-3.4e38 (r32)"
                              : "a finite real number (r64)";
        return std::nullopt;
      }
      if (type.bytes == 4) {
        const auto f = static_cast<float>(d);
        std::uint32_t raw = 0;
        std::memcpy(&raw, &f, 4);
        put_le(out, raw, 4);
      } else {
        std::uint64_t raw = 0;
        std::memcpy(&raw, &d, 8);
        put_le(out, raw, 8);
      }
      return out;
    }
    case ValueKind::kString: {
      if (text.size() >= 2 && text.front() == '"' && text.back() == '"')
        text = text.substr(1, text.size() - 2);
      out.assign(text.begin(), text.end());
      return out;
    }
    case ValueKind::kOctets: {
      std::string hex;
      for (char c : text) {
        if (c != ' ' && c != ':') hex.push_back(c);
      }
      if (hex.size() % 2 != 0) {
        why = "hex bytes (an even number of hex digits)";
        return std::nullopt;
      }
      for (std::size_t i = 0; i < hex.size(); i += 2) {
        const int hi = hex_digit(hex[i]);
        const int lo = hex_digit(hex[i + 1]);
        if (hi < 0 || lo < 0) {
          why = "hex bytes, found '" + hex.substr(i, 2) + "'";
          return std::nullopt;
        }
        out.push_back(static_cast<std::uint8_t>(hi * 16 + lo));
      }
      return out;
    }
  }
  why = "unknown type";
  return std::nullopt;
}

std::string format_value(const ValueType& type, const std::vector<std::uint8_t>& bytes) {
  char buf[64];
  const std::size_t n = type.bytes;
  switch (type.kind) {
    case ValueKind::kBool:
      return get_le(bytes, 1) != 0 ? "1" : "0";
    case ValueKind::kSigned: {
      const std::uint64_t raw = get_le(bytes, n);
      const unsigned bits = 8u * static_cast<unsigned>(n);
      std::int64_t v = static_cast<std::int64_t>(raw);
      if (bits < 64) {
        const std::uint64_t sign = std::uint64_t{1} << (bits - 1);
        v = static_cast<std::int64_t>((raw ^ sign) - sign);
      }
      return std::to_string(v);
    }
    case ValueKind::kUnsigned:
      return std::to_string(get_le(bytes, n));
    case ValueKind::kHex:
      std::snprintf(buf, sizeof buf, "0x%0*llX", static_cast<int>(2 * n),
                    static_cast<unsigned long long>(get_le(bytes, n)));
      return buf;
    case ValueKind::kReal:
      if (n == 4) {
        const auto raw = static_cast<std::uint32_t>(get_le(bytes, 4));
        float f = 0;
        std::memcpy(&f, &raw, 4);
        std::snprintf(buf, sizeof buf, "%.7g", static_cast<double>(f));
      } else {
        const std::uint64_t raw = get_le(bytes, 8);
        double d = 0;
        std::memcpy(&d, &raw, 8);
        std::snprintf(buf, sizeof buf, "%.15g", d);
      }
      return buf;
    case ValueKind::kString: {
      std::string s;
      for (std::uint8_t c : bytes) {
        if (c == 0) break;
        s.push_back(c >= 0x20 && c < 0x7F ? static_cast<char>(c) : '?');
      }
      return "\"" + s + "\"";
    }
    case ValueKind::kOctets: {
      std::string s;
      for (std::size_t i = 0; i < bytes.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%s%02X", i ? " " : "", bytes[i]);
        s += buf;
      }
      return s;
    }
  }
  return "?";
}

}  // namespace planter::cantool
