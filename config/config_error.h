#pragma once
#include <stdexcept>
#include <string>

namespace planter::config {

// A bad configuration file: one message naming the file, line, key and what is allowed.
// Line 0 means the file as a whole (it cannot be opened, or is not a regular file).
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& file, int line, const std::string& key, const std::string& what)
      : std::runtime_error(message(file, line, key, what)), file_(file), line_(line), key_(key) {}
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] int line() const { return line_; }
  [[nodiscard]] const std::string& key() const { return key_; }

 private:
  static std::string message(const std::string& file, int line, const std::string& key,
                             const std::string& what) {
    std::string m = file;
    if (line > 0) m.append(":").append(std::to_string(line));
    m.append(": ");
    if (!key.empty()) m.append("'").append(key).append("': ");
    return m.append(what);
  }
  std::string file_;
  int line_;
  std::string key_;
};

}  // namespace planter::config
