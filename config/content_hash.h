#pragma once
// A text's 64-bit FNV-1a hash as 16 hex digits: the key under which a run's result is kept
// (planter-dem calibrate's runs, a plan's scenario). It tells a changed input from the same
// one; it is no protection against someone forging a collision.
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace planter::config {

inline std::string content_hash(std::string_view text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, h);
  return buf;
}

}  // namespace planter::config
