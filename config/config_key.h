#pragma once
// One row per configuration key: which file it belongs in, its table, type, unit, range,
// default and meaning. Each file kind declares its keys once in a table (config/board_keys.h,
// sim/runner/scenario_keys.h, dem/dem_keys.h); the loaders read through the rows, and the
// wrong-file messages, `--list-keys` and docs/configuration.md are all made from the same rows.
#include <cstdint>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <string_view>

namespace planter::config {

enum class FileKind : std::uint8_t {
  kBoard,          // boards/<board>/board.toml: the bus, the lines, the loop's timing
  kMachine,        // machines/<machine>.toml: the mechanism, the loops, the nodes
  kCalibration,    // boards/<board>/calibration.toml: one unit's measured values
  kScenario,       // scenarios/<name>.toml: the field, the seedlings, the simulated plant
  kSeedlingForce,  // models/<name>.toml: planter-dem reduce's seedling force law
  kDemSetup,       // planter-dem --params: the bonded-particle seedling and its test
};
inline constexpr std::size_t kFileKindCount = 6;

// "the machine file (machines/<machine>.toml)"
std::string_view file_kind_text(FileKind kind);

enum class KeyType : std::uint8_t {
  kNumber,
  kInteger,
  kBoolean,
  kString,
  kStrings,  // an array of strings
  kTable,    // a table or an array of tables whose keys are rows of their own
  kRetired,  // no longer read; `meaning` says what replaced it
};

inline constexpr double kNoDefault = std::numeric_limits<double>::quiet_NaN();

struct ConfigKey {
  FileKind file{};
  std::string_view table;  // dotted path: "control", "nodes.*" (any node), "route.stops[]"
  std::string_view name;
  KeyType type{};
  double fallback = kNoDefault;  // numbers, integers, booleans (0/1) when the key is absent
  double min = 0.0, max = 0.0;   // numbers and integers
  std::string_view unit;         // "" for a pure number
  std::string_view meaning;
  std::string_view default_text;  // strings, and defaults that depend on other keys
  bool required = false;
};

// Rows, built by kind so that each names only what it has.
constexpr ConfigKey number_key(FileKind f, std::string_view table, std::string_view name,
                               double fallback, double min, double max, std::string_view unit,
                               std::string_view meaning, std::string_view default_text = {}) {
  return {f, table, name, KeyType::kNumber, fallback, min, max, unit, meaning, default_text, false};
}
constexpr ConfigKey integer_key(FileKind f, std::string_view table, std::string_view name,
                                double fallback, double min, double max, std::string_view unit,
                                std::string_view meaning, std::string_view default_text = {}) {
  return {f,   table, name,    KeyType::kInteger, fallback, min,
          max, unit,  meaning, default_text,      false};
}
constexpr ConfigKey required_number_key(FileKind f, std::string_view table, std::string_view name,
                                        double min, double max, std::string_view unit,
                                        std::string_view meaning) {
  return {f, table, name, KeyType::kNumber, kNoDefault, min, max, unit, meaning, {}, true};
}
constexpr ConfigKey required_integer_key(FileKind f, std::string_view table, std::string_view name,
                                         double min, double max, std::string_view meaning) {
  return {f, table, name, KeyType::kInteger, kNoDefault, min, max, "", meaning, {}, true};
}
constexpr ConfigKey bool_key(FileKind f, std::string_view table, std::string_view name,
                             bool fallback, std::string_view meaning,
                             std::string_view default_text = {}) {
  return {f,       table,        name, KeyType::kBoolean, fallback ? 1.0 : 0.0, 0, 0, "",
          meaning, default_text, false};
}
// `fallback` is the value when the key is absent; `required` refuses a file without it.
constexpr ConfigKey string_key(FileKind f, std::string_view table, std::string_view name,
                               std::string_view fallback, std::string_view meaning,
                               bool required = false) {
  return {f, table, name, KeyType::kString, kNoDefault, 0, 0, "", meaning, fallback, required};
}
constexpr ConfigKey strings_key(FileKind f, std::string_view table, std::string_view name,
                                std::string_view meaning) {
  return {f, table, name, KeyType::kStrings, kNoDefault, 0, 0, "", meaning, {}, false};
}
constexpr ConfigKey table_key(FileKind f, std::string_view table, std::string_view name,
                              std::string_view meaning, bool required = false) {
  return {f, table, name, KeyType::kTable, kNoDefault, 0, 0, "", meaning, {}, required};
}
// A key no longer read: `message` says what replaced it, for a user with an old file.
constexpr ConfigKey retired_key(FileKind f, std::string_view table, std::string_view name,
                                std::string_view message) {
  return {f, table, name, KeyType::kRetired, kNoDefault, 0, 0, "", message, {}, false};
}

// The row of `dotted` ("table.name"); a name that is not in the table does not compile.
template <class Rows>
consteval const ConfigKey& key_in(const Rows& rows, std::string_view dotted) {
  for (const ConfigKey& k : rows) {
    const std::size_t t = k.table.size();
    if (dotted.size() == t + 1 + k.name.size() && dotted.substr(0, t) == k.table &&
        dotted[t] == '.' && dotted.substr(t + 1) == k.name)
      return k;
  }
  throw "no such configuration key in this table";  // a compile error in a consteval call
}

// Every row a loader knows of, its own file's and the other files' (for wrong-file messages).
struct KeyTables {
  FileKind here{};
  std::span<const std::span<const ConfigKey>> rows;
};

// A row's figure as messages and the reference print it (the shortest of printf's %g forms).
std::string number_text(double v);
// A row's bound or default as an integer: doubles hold integers exactly to 2^53, and the int64
// ends (a seed's range) saturate instead of overflowing.
std::int64_t row_integer(double v);

// "table.name" ("can.bitrate"), as messages name a key.
inline std::string dotted_name(const ConfigKey& k) {
  return k.table.empty() ? std::string(k.name) : std::string(k.table) + "." + std::string(k.name);
}

// Whether a section at `path` ("nodes.disc_drive", "route.stops[2]") is the row's table.
bool table_matches(std::string_view row_table, std::string_view path);

// The row of `table`.`name` at run time, for a loader that reads one set of rows into several
// tables; nullptr when there is none.
const ConfigKey* find_key(std::span<const ConfigKey> rows, std::string_view table,
                          std::string_view name);

// What follows "unknown key" for `name` in the section at `path`: the file it belongs in and
// what it means, what replaced a retired key, or the keys this table does hold.
std::string unknown_key_text(const KeyTables& tables, std::string_view path, std::string_view name);

// The reference `--list-keys` prints: one block per file kind, one line per key.
std::string key_reference(std::span<const std::span<const ConfigKey>> rows);
// Writes it whole to `out` and flushes; false when the write failed (a full disk, a closed pipe).
bool write_key_reference(std::FILE* out, std::span<const std::span<const ConfigKey>> rows);

}  // namespace planter::config
