#pragma once
// Bounds on a TOML text's shape, checked before the parser sees it (issue 28, item 8): toml++
// recurses once per part of a dotted key and per level of nesting, so a key of tens of
// thousands of parts overflows the stack. No configuration file of this project comes near
// these limits.
#include <string>

namespace planter::config {

inline constexpr int kTomlMaxKeyParts = 64;  // a.b.c has 3
inline constexpr int kTomlMaxNesting = 32;   // [ and { open at once
inline constexpr std::size_t kTomlMaxLineBytes = 64u << 10;

// Throws ConfigError (file, line, the limit) when the text exceeds one of the bounds.
void check_toml_bounds(const std::string& text, const std::string& file);

}  // namespace planter::config
