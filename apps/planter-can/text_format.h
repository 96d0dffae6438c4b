#pragma once
// printf-style formatting into a std::string, for the tool's one-line messages (at most 255
// characters; longer text is cut).
#include <cstdio>
#include <string>

namespace planter::cantool {

template <typename... Args>
std::string format_text(const char* format, Args... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

}  // namespace planter::cantool
