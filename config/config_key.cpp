#include "config/config_key.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace planter::config {
namespace {

std::vector<std::string_view> segments(std::string_view path) {
  std::vector<std::string_view> out;
  while (!path.empty()) {
    const std::size_t dot = path.find('.');
    out.push_back(path.substr(0, dot));
    if (dot == std::string_view::npos) break;
    path.remove_prefix(dot + 1);
  }
  return out;
}

// "*" is any node; "stops[]" is any element of the array "stops".
bool segment_matches(std::string_view row, std::string_view got) {
  if (row == "*") return true;
  if (row.size() > 2 && row.substr(row.size() - 2) == "[]") {
    const std::string_view array = row.substr(0, row.size() - 2);
    return got.size() > array.size() + 2 && got.substr(0, array.size()) == array &&
           got[array.size()] == '[' && got.back() == ']';
  }
  return row == got;
}

// Whether `got` (a section's path, split) is the row's `path` or a table on the way into it.
bool leads_into(const std::vector<std::string_view>& path,
                const std::vector<std::string_view>& got) {
  if (got.size() > path.size()) return false;
  for (std::size_t i = 0; i < got.size(); ++i)
    if (!segment_matches(path[i], got[i])) return false;
  return true;
}

// The row's table and name, split.
std::vector<std::string_view> row_path(const ConfigKey& k) {
  std::vector<std::string_view> row = segments(k.table);
  row.push_back(k.name);
  return row;
}

}  // namespace

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::int64_t row_integer(double v) {
  if (v >= 9.2233720368547758e18) return INT64_MAX;
  if (v <= -9.2233720368547758e18) return INT64_MIN;
  return static_cast<std::int64_t>(v);
}

namespace {

// An integer row's figures as integers (1000000, not 1e+06); the int64 end as itself.
std::string figure(const ConfigKey& k, double v) {
  return k.type == KeyType::kInteger ? std::to_string(row_integer(v)) : number_text(v);
}

std::string default_of(const ConfigKey& k) {
  if (k.required) return "required";
  if (!k.default_text.empty()) return std::string(k.default_text);
  if (std::isnan(k.fallback)) return "-";
  if (k.type == KeyType::kBoolean) return k.fallback != 0.0 ? "true" : "false";
  return figure(k, k.fallback);
}

std::string range_of(const ConfigKey& k) {
  switch (k.type) {
    case KeyType::kNumber:
    case KeyType::kInteger: {
      std::string range(1, '[');
      range += figure(k, k.min);
      range += ", ";
      range += figure(k, k.max);
      range += ']';
      return range;
    }
    case KeyType::kBoolean:
      return "true/false";
    case KeyType::kString:
      return "text";
    case KeyType::kStrings:
      return "[texts]";
    case KeyType::kTable:
      return "table";
    case KeyType::kRetired:
      break;
  }
  return "";
}

std::string padded(std::string s, std::size_t width) {
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s + "  ";
}

}  // namespace

std::string_view file_kind_text(FileKind kind) {
  switch (kind) {
    case FileKind::kBoard:
      return "the board file (boards/<board>/board.toml: the bus, the lines, the encoder's counts "
             "and filter, the loop's timing, the console)";
    case FileKind::kMachine:
      return "the machine file (machines/<machine>.toml: the disc, the loops, the planting "
             "monitor, the nodes)";
    case FileKind::kCalibration:
      return "the unit's calibration (boards/<board>/calibration.toml: what planter-can "
             "calibrate measured)";
    case FileKind::kScenario:
      return "a scenario (scenarios/<name>.toml: the field, the seedlings, the simulated plant)";
    case FileKind::kSeedlingForce:
      return "a seedling force model (models/<name>.toml, written by planter-dem reduce)";
    case FileKind::kDemSetup:
      return "planter-dem's parameters (--params: the bonded-particle seedling and its "
             "compression test)";
  }
  return "a configuration file";
}

bool table_matches(std::string_view row_table, std::string_view path) {
  const std::vector<std::string_view> row = segments(row_table);
  const std::vector<std::string_view> got = segments(path);
  return row.size() == got.size() && leads_into(row, got);
}

const ConfigKey* find_key(std::span<const ConfigKey> rows, std::string_view table,
                          std::string_view name) {
  for (const ConfigKey& k : rows)
    if (k.table == table && k.name == name) return &k;
  return nullptr;
}

std::string unknown_key_text(const KeyTables& tables, std::string_view path,
                             std::string_view name) {
  const std::vector<std::string_view> got = segments(path);
  std::vector<std::string_view> got_key = got;
  got_key.push_back(name);
  bool elsewhere[kFileKindCount] = {};
  std::string_view meaning;
  std::vector<std::string_view> held;
  for (std::span<const ConfigKey> rows : tables.rows) {
    for (const ConfigKey& k : rows) {
      const bool here = k.file == tables.here;
      if (k.type == KeyType::kRetired) {
        if (here && table_matches(k.table, path) && k.name == name) return std::string(k.meaning);
        continue;
      }
      const std::vector<std::string_view> row = row_path(k);
      if (here) {
        // The keys and tables this section holds: the next segment after its path.
        const bool under = row.size() > got.size() && leads_into(row, got);
        if (under && std::find(held.begin(), held.end(), row[got.size()]) == held.end())
          held.push_back(row[got.size()]);
        continue;
      }
      if (!leads_into(row, got_key)) continue;
      elsewhere[static_cast<std::size_t>(k.file)] = true;
      if (table_matches(k.table, path) && k.name == name) meaning = k.meaning;
    }
  }
  std::string where;
  for (std::size_t i = 0; i < kFileKindCount; ++i) {
    if (!elsewhere[i]) continue;
    if (!where.empty()) where += " or ";
    where += file_kind_text(static_cast<FileKind>(i));
  }
  if (!where.empty()) {
    return "unknown key here; this key belongs in " + where +
           (meaning.empty() ? std::string() : ": " + std::string(meaning));
  }
  if (held.empty()) return "unknown key";
  std::string list;
  for (std::string_view h : held) {
    if (!list.empty()) list += ", ";
    list += h;
  }
  return "unknown key; " + std::string(path.empty() ? "this file" : "this table") + " holds " +
         list + " (--list-keys prints them all)";
}

std::string key_reference(std::span<const std::span<const ConfigKey>> rows) {
  std::string out;
  int kind = -1;
  std::string_view table = "\x01";
  for (std::span<const ConfigKey> group : rows) {
    for (const ConfigKey& k : group) {
      if (k.type == KeyType::kRetired) continue;
      if (static_cast<int>(k.file) != kind) {
        kind = static_cast<int>(k.file);
        if (!out.empty()) out += '\n';
        out += file_kind_text(k.file);
        out += '\n';
        table = "\x01";
      }
      if (k.table != table) {
        table = k.table;
        out += "  [";
        out += table.empty() ? "(top level)" : table;
        out += "]\n";
      }
      std::string line = "    " + padded(std::string(k.name), 28) + padded(default_of(k), 13) +
                         padded(std::string(k.unit), 8) + padded(range_of(k), 18) +
                         std::string(k.meaning);
      out += line + "\n";
    }
  }
  return out;
}

bool write_key_reference(std::FILE* out, std::span<const std::span<const ConfigKey>> rows) {
  const std::string text = key_reference(rows);
  return std::fwrite(text.data(), 1, text.size(), out) == text.size() && std::fflush(out) == 0;
}

}  // namespace planter::config
