#include "config/toml_section.h"

#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "config/input_file.h"
#include "config/toml_bounds.h"

namespace planter::config {

TomlSection::TomlSection(const toml::table& table, std::string path, std::string file,
                         KeyTables keys)
    : table_(&table), keys_(keys), path_(std::move(path)), file_(std::move(file)) {}
TomlSection::~TomlSection() = default;
TomlSection::TomlSection(TomlSection&&) noexcept = default;

std::string TomlSection::dotted(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

int TomlSection::line() const { return static_cast<int>(table_->source().begin.line); }

int TomlSection::line_of(const std::string& key) const {
  const toml::node* n = table_->get(key);
  return n != nullptr ? static_cast<int>(n->source().begin.line) : line();
}

void TomlSection::fail(const std::string& key, const std::string& what) const {
  throw ConfigError(file_, line_of(key), dotted(key), what);
}

const toml::node* TomlSection::get(const std::string& key) {
  used_.insert(key);
  return table_->get(key);
}

bool TomlSection::has(const std::string& key) const { return table_->contains(key); }

double TomlSection::number(const std::string& key, double fallback, double min, double max,
                           const char* unit) {
  const toml::node* n = get(key);
  if (n == nullptr) return fallback;
  double v = 0;
  if (auto f = n->value_exact<double>()) {
    v = *f;
  } else if (auto i = n->value_exact<std::int64_t>()) {
    v = static_cast<double>(*i);
  } else {
    fail(key, "must be a number");
  }
  if (!std::isfinite(v) || v < min || v > max) {
    fail(key, number_text(v) + " is out of range; allowed [" + number_text(min) + ", " +
                  number_text(max) + "]" +
                  (unit[0] != 0 ? std::string(" ") + unit : std::string()));
  }
  return v;
}

double TomlSection::required_number(const std::string& key, double min, double max,
                                    const char* unit) {
  if (!has(key))
    throw ConfigError(
        file_, line(), dotted(key),
        "is required (a number in [" + number_text(min) + ", " + number_text(max) + "])");
  return number(key, 0.0, min, max, unit);
}

std::int64_t TomlSection::integer(const std::string& key, std::int64_t fallback, std::int64_t min,
                                  std::int64_t max) {
  const toml::node* n = get(key);
  if (n == nullptr) return fallback;
  auto i = n->value_exact<std::int64_t>();
  if (!i) fail(key, "must be an integer");
  if (*i < min || *i > max) {
    fail(key, std::to_string(*i) + " is out of range; allowed [" + std::to_string(min) + ", " +
                  std::to_string(max) + "]");
  }
  return *i;
}

std::int64_t TomlSection::required_integer(const std::string& key, std::int64_t min,
                                           std::int64_t max) {
  if (!has(key))
    throw ConfigError(
        file_, line(), dotted(key),
        "is required (an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "])");
  return integer(key, 0, min, max);
}

bool TomlSection::boolean(const std::string& key, bool fallback) {
  const toml::node* n = get(key);
  if (n == nullptr) return fallback;
  auto b = n->value_exact<bool>();
  if (!b) fail(key, "must be true or false");
  return *b;
}

void TomlSection::reject_control_characters(const std::string& key, const std::string& s) const {
  // Names and paths go into CSV metadata lines, HTML titles and messages: one line each.
  for (const char c : s) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
      fail(key, "must not hold control characters (newline, tab, ...)");
  }
}

std::string TomlSection::string(const std::string& key, const std::string& fallback) {
  const toml::node* n = get(key);
  if (n == nullptr) return fallback;
  auto s = n->value_exact<std::string>();
  if (!s) fail(key, "must be a string");
  reject_control_characters(key, *s);
  return *s;
}

std::vector<std::string> TomlSection::strings(const std::string& key) {
  const toml::node* n = get(key);
  std::vector<std::string> out;
  if (n == nullptr) return out;
  const toml::array* a = n->as_array();
  if (a == nullptr) fail(key, "must be an array of strings");
  for (const auto& item : *a) {
    auto s = item.value_exact<std::string>();
    if (!s) fail(key, "must be an array of strings");
    reject_control_characters(key, *s);
    out.push_back(*s);
  }
  return out;
}

std::optional<TomlSection> TomlSection::table(const std::string& key) {
  const toml::node* n = get(key);
  if (n == nullptr) return std::nullopt;
  const toml::table* t = n->as_table();
  if (t == nullptr) fail(key, "must be a table");
  return TomlSection(*t, dotted(key), file_, keys_);
}

std::vector<TomlSection> TomlSection::array_of_tables(const std::string& key) {
  const toml::node* n = get(key);
  std::vector<TomlSection> out;
  if (n == nullptr) return out;
  const toml::array* a = n->as_array();
  if (a == nullptr) fail(key, "must be an array of tables");
  std::size_t i = 0;
  for (const auto& item : *a) {
    const toml::table* t = item.as_table();
    if (t == nullptr) fail(key, "must be an array of tables");
    out.emplace_back(*t, dotted(key) + "[" + std::to_string(i++) + "]", file_, keys_);
  }
  return out;
}

std::vector<std::string> TomlSection::keys() const {
  std::vector<std::string> out;
  for (const auto& [k, v] : *table_) out.emplace_back(k.str());
  return out;
}

void TomlSection::reject_unknown_keys() const {
  for (const auto& [k, v] : *table_) {
    const std::string key(k.str());
    if (used_.count(key) == 0) {
      throw ConfigError(file_, static_cast<int>(v.source().begin.line), dotted(key),
                        unknown_key_text(keys_, path_, key));
    }
  }
}

const ConfigKey& TomlSection::own(const ConfigKey& k) const {
  // A row read from the wrong table is the loader's bug, not the user's.
  if (!table_matches(k.table, path_))
    throw std::logic_error("key " + std::string(k.table) + "." + std::string(k.name) +
                           " read in table '" + path_ + "'");
  return k;
}

void TomlSection::no_default_needs_key(const ConfigKey& k) const {
  // A row without a default is read only where its key is present (the loader asks has()).
  if (std::isnan(k.fallback) && !has(std::string(k.name)))
    throw std::logic_error("key " + std::string(k.name) + " has no default and is absent");
}

double TomlSection::number(const ConfigKey& k) {
  own(k);
  if (k.required)
    return required_number(std::string(k.name), k.min, k.max, std::string(k.unit).c_str());
  no_default_needs_key(k);
  return number(k, k.fallback);
}

double TomlSection::number(const ConfigKey& k, double fallback) {
  own(k);
  return number(std::string(k.name), fallback, k.min, k.max, std::string(k.unit).c_str());
}

std::int64_t TomlSection::integer(const ConfigKey& k) {
  own(k);
  if (k.required)
    return required_integer(std::string(k.name), row_integer(k.min), row_integer(k.max));
  no_default_needs_key(k);
  return integer(k, std::isnan(k.fallback) ? 0 : row_integer(k.fallback));
}

std::int64_t TomlSection::integer(const ConfigKey& k, std::int64_t fallback) {
  own(k);
  return integer(std::string(k.name), fallback, row_integer(k.min), row_integer(k.max));
}

bool TomlSection::boolean(const ConfigKey& k) {
  own(k);
  return boolean(std::string(k.name), k.fallback != 0.0);
}

bool TomlSection::boolean(const ConfigKey& k, bool fallback) {
  own(k);
  return boolean(std::string(k.name), fallback);
}

std::string TomlSection::string(const ConfigKey& k) {
  own(k);
  if (k.required && !has(std::string(k.name)))
    throw ConfigError(file_, line(), dotted(std::string(k.name)),
                      "is required: " + std::string(k.meaning));
  return string(std::string(k.name), std::string(k.default_text));
}

std::string TomlSection::string(const ConfigKey& k, const std::string& fallback) {
  own(k);
  return string(std::string(k.name), fallback);
}

std::vector<std::string> TomlSection::strings(const ConfigKey& k) {
  own(k);
  return strings(std::string(k.name));
}

TomlDocument::TomlDocument(const std::string& file, KeyTables keys) : file_(file), keys_(keys) {
  const std::string text = read_input_file(file);
  check_toml_bounds(text, file);
  try {
    table_ = std::make_unique<toml::table>(toml::parse(text, file));
  } catch (const toml::parse_error& e) {
    throw ConfigError(file, static_cast<int>(e.source().begin.line), "",
                      std::string(e.description()));
  }
}

TomlDocument::~TomlDocument() = default;

TomlSection TomlDocument::root() { return TomlSection(*table_, "", file_, keys_); }

}  // namespace planter::config
