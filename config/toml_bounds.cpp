#include "config/toml_bounds.h"

#include "config/config_error.h"

namespace planter::config {
namespace {
bool bare_key_char(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-';
}
}  // namespace

void check_toml_bounds(const std::string& text, const std::string& file) {
  int line = 1, depth = 0, parts = 1;
  std::size_t line_start = 0;
  auto fail = [&](const std::string& what) { throw ConfigError(file, line, "", what); };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = i + 1;
      parts = 1;
      continue;
    }
    if (i - line_start >= kTomlMaxLineBytes)
      fail("a line longer than " + std::to_string(kTomlMaxLineBytes) + " bytes");
    if (c == '#') {  // a comment runs to the end of the line
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
      continue;
    }
    if (c == '"' || c == '\'') {
      // A string, one-line or multi-line ("""...""" or '''...'''); a basic string's escapes.
      const bool multi = text.compare(i, 3, std::string(3, c)) == 0;
      const std::string close = multi ? std::string(3, c) : std::string(1, c);
      std::size_t j = i + close.size();
      while (j < text.size()) {
        if (c == '"' && text[j] == '\\') {
          j += 2;
          continue;
        }
        if (text[j] == '\n') {
          if (!multi) break;  // the parser says what is wrong
          ++line;
          line_start = j + 1;
        }
        if (text.compare(j, close.size(), close) == 0) break;
        ++j;
      }
      i = std::min(text.size(), j + close.size()) - 1;
      continue;  // a quoted key part keeps the count of parts
    }
    if (c == '.') {
      if (++parts > kTomlMaxKeyParts)
        fail("a key of more than " + std::to_string(kTomlMaxKeyParts) + " dotted parts");
      continue;
    }
    if (c == '[' || c == '{') {
      if (++depth > kTomlMaxNesting)
        fail("arrays or tables nested more than " + std::to_string(kTomlMaxNesting) + " deep");
    } else if (c == ']' || c == '}') {
      if (depth > 0) --depth;
    }
    if (!bare_key_char(c) && c != ' ' && c != '\t') parts = 1;
  }
}

}  // namespace planter::config
