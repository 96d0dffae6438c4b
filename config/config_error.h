#pragma once
#include <stdexcept>
#include <string>

namespace planter::config {

// A bad configuration file: one message naming the file, line, key and what is allowed.
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& file, int line, const std::string& key, const std::string& what)
      : std::runtime_error(file + ":" + std::to_string(line) + ": " +
                           (key.empty() ? "" : "'" + key + "': ") + what),
        file_(file),
        line_(line),
        key_(key) {}
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] int line() const { return line_; }
  [[nodiscard]] const std::string& key() const { return key_; }

 private:
  std::string file_;
  int line_;
  std::string key_;
};

}  // namespace planter::config
