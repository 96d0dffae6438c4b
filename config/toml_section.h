#pragma once
// Reads one TOML table with checks: type, range, unknown keys. Every failure throws a
// ConfigError naming the file, line and dotted key.
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "config/config_error.h"

namespace toml {
inline namespace v3 {
class table;
class node;
}  // namespace v3
}  // namespace toml

namespace planter::config {

class TomlSection {
 public:
  TomlSection(const toml::table& table, std::string path, std::string file);
  ~TomlSection();
  TomlSection(TomlSection&&) noexcept;

  double number(const std::string& key, double fallback, double min, double max,
                const char* unit = "");
  double required_number(const std::string& key, double min, double max, const char* unit = "");
  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t min,
                       std::int64_t max);
  std::int64_t required_integer(const std::string& key, std::int64_t min, std::int64_t max);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  std::vector<std::string> strings(const std::string& key);
  bool has(const std::string& key) const;
  std::optional<TomlSection> table(const std::string& key);
  std::vector<TomlSection> array_of_tables(const std::string& key);
  std::vector<std::string> keys() const;
  // Throws for any key that was never read: a typo must not pass silently. `hint` (if any)
  // follows "unknown key" and says where such a key belongs.
  void reject_unknown_keys(const std::string& hint = "") const;

  [[nodiscard]] int line() const;
  [[nodiscard]] int line_of(const std::string& key) const;
  [[nodiscard]] std::string dotted(const std::string& key) const;
  [[nodiscard]] const std::string& file() const { return file_; }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  // fail()s when a string value holds a control character (newline, tab, ...).
  void reject_control_characters(const std::string& key, const std::string& s) const;

 private:
  const toml::node* get(const std::string& key);
  const toml::table* table_;
  std::string path_;
  std::string file_;
  std::set<std::string> used_;
};

// Parses a file; syntax errors become ConfigError with the parser's line.
class TomlDocument {
 public:
  explicit TomlDocument(const std::string& file);
  ~TomlDocument();
  TomlSection root();

 private:
  std::string file_;
  std::unique_ptr<toml::table> table_;
};

}  // namespace planter::config
