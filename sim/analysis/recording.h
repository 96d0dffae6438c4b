#pragma once
// A recording in the PRODUCT.md format, as the analysis reads it: `#` metadata lines, a
// header of signal names, one row per sample, time strictly increasing. Columns may be
// absent; `state` is kept as text. Every defect is one RecordingError with its line.
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace planter::analysis {

class RecordingError : public std::runtime_error {
 public:
  RecordingError(const std::string& file, int line, const std::string& what)
      : std::runtime_error(file + ":" + std::to_string(line) + ": " + what), line_(line) {}
  [[nodiscard]] int line() const { return line_; }

 private:
  int line_;
};

struct Recording {
  std::string file;
  std::map<std::string, std::string> metadata;
  std::vector<double> t;
  std::map<std::string, std::vector<double>> signals;  // numeric columns by name
  std::vector<std::string> state;                      // empty when there is no state column
  [[nodiscard]] bool has(const std::string& name) const { return signals.count(name) != 0; }
  [[nodiscard]] const std::vector<double>& at(const std::string& name) const {
    return signals.at(name);
  }
  [[nodiscard]] std::size_t size() const { return t.size(); }
};

// Parses CSV text (file names the messages). Needs at least `min_rows` rows.
Recording parse_recording(const std::string& text, const std::string& file,
                          std::size_t min_rows = 50);
// Reads and parses a file.
Recording load_recording(const std::string& path, std::size_t min_rows = 50);

}  // namespace planter::analysis
