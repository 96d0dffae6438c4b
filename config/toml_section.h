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
#include "config/config_key.h"

namespace toml {
inline namespace v3 {
class table;
class node;
}  // namespace v3
}  // namespace toml

namespace planter::config {

class TomlSection {
 public:
  TomlSection(const toml::table& table, std::string path, std::string file, KeyTables keys = {});
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
  // Reads through a key's row (config/config_key.h): its name, range, unit and default, or
  // `fallback` where the default depends on other keys. The row must be this table's.
  double number(const ConfigKey& k);
  double number(const ConfigKey& k, double fallback);
  std::int64_t integer(const ConfigKey& k);
  std::int64_t integer(const ConfigKey& k, std::int64_t fallback);
  bool boolean(const ConfigKey& k);
  bool boolean(const ConfigKey& k, bool fallback);
  std::string string(const ConfigKey& k);  // default_text when absent
  std::string string(const ConfigKey& k, const std::string& fallback);
  std::vector<std::string> strings(const ConfigKey& k);
  bool has(const ConfigKey& k) const { return has(std::string(k.name)); }
  bool has(const std::string& key) const;
  std::optional<TomlSection> table(const std::string& key);
  std::vector<TomlSection> array_of_tables(const std::string& key);
  std::vector<std::string> keys() const;
  // Throws for any key that was never read: a typo must not pass silently. The message says
  // which file such a key belongs in, or what replaced it, or what this table holds, from the
  // key tables the document was opened with.
  void reject_unknown_keys() const;

  [[nodiscard]] int line() const;
  [[nodiscard]] int line_of(const std::string& key) const;
  [[nodiscard]] std::string dotted(const std::string& key) const;
  [[nodiscard]] const std::string& file() const { return file_; }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;
  [[noreturn]] void fail(const ConfigKey& k, const std::string& what) const {
    fail(std::string(k.name), what);
  }
  // fail()s when a string value holds a control character (newline, tab, ...).
  void reject_control_characters(const std::string& key, const std::string& s) const;

 private:
  const toml::node* get(const std::string& key);
  const ConfigKey& own(const ConfigKey& k) const;
  void no_default_needs_key(const ConfigKey& k) const;
  const toml::table* table_;
  KeyTables keys_;
  std::string path_;
  std::string file_;
  std::set<std::string> used_;
};

// Parses a file; syntax errors become ConfigError with the parser's line.
class TomlDocument {
 public:
  // `keys`: the rows of this file kind and of the others, for the unknown-key messages.
  explicit TomlDocument(const std::string& file, KeyTables keys = {});
  ~TomlDocument();
  TomlSection root();

 private:
  std::string file_;
  KeyTables keys_;
  std::unique_ptr<toml::table> table_;
};

}  // namespace planter::config
