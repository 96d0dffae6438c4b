#include "sim/analysis/recording.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "config/input_file.h"

namespace planter::analysis {
namespace {

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (char c : line) {
    if (c == ',') {
      out.push_back(cell);
      cell.clear();
    } else if (c != '\r') {
      cell += c;
    }
  }
  out.push_back(cell);
  return out;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

}  // namespace

Recording parse_recording(const std::string& text, const std::string& file, std::size_t min_rows) {
  Recording r;
  r.file = file;
  // A CSV saved on Windows may start with a UTF-8 byte-order mark: it is not part of "t".
  std::istringstream in(config::starts_with_utf8_bom(text) ? text.substr(3) : text);
  std::string line;
  int line_no = 0;
  std::vector<std::string> header;
  int state_col = -1, t_col = -1;
  std::vector<std::vector<double>*> columns;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (header.empty()) {
      if (line.empty()) continue;
      if (line[0] == '#') {
        const auto colon = line.find(':');
        if (colon != std::string::npos)
          r.metadata[trim(line.substr(1, colon - 1))] = trim(line.substr(colon + 1));
        continue;
      }
      header = split_commas(line);
      std::set<std::string> seen;
      for (std::size_t c = 0; c < header.size(); ++c) {
        header[c] = trim(header[c]);
        const std::string& name = header[c];
        if (name.empty())
          throw RecordingError(file, line_no,
                               "header: column " + std::to_string(c + 1) + " has no name");
        if (!seen.insert(name).second)
          throw RecordingError(file, line_no,
                               "header: column '" + config::excerpt(name) + "' appears twice");
        if (name == "t") t_col = static_cast<int>(c);
        if (name == "state") state_col = static_cast<int>(c);
      }
      if (t_col < 0)
        throw RecordingError(file, line_no,
                             "header: no 't' column (the first line after the # comments must "
                             "be the header of signal names, with t in seconds)");
      for (std::size_t c = 0; c < header.size(); ++c) {
        columns.push_back(static_cast<int>(c) == state_col || static_cast<int>(c) == t_col
                              ? nullptr
                              : &r.signals[header[c]]);
      }
      continue;
    }
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_commas(line);
    if (cells.size() != header.size())
      throw RecordingError(
          file, line_no,
          std::to_string(cells.size()) + " cells, the header has " + std::to_string(header.size()));
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (static_cast<int>(c) == state_col) {
        r.state.push_back(trim(cells[c]));
        continue;
      }
      const std::string cell = trim(cells[c]);
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(cell.c_str(), &end);
      // ERANGE with a tiny result is underflow (1e-310 reads as a denormal or 0: a number).
      const bool overflow = errno == ERANGE && std::fabs(v) == HUGE_VAL;
      if (cell.empty() || end != cell.c_str() + cell.size() || overflow)
        throw RecordingError(file, line_no,
                             "column '" + config::excerpt(header[c]) + "': '" +
                                 config::excerpt(cell) + "' is not a number");
      if (!std::isfinite(v))
        throw RecordingError(file, line_no,
                             "column '" + config::excerpt(header[c]) +
                                 "': " + config::excerpt(cell) +
                                 " (NaN or infinite values are not allowed)");
      if (static_cast<int>(c) == t_col) {
        if (!r.t.empty() && v <= r.t.back())
          throw RecordingError(
              file, line_no,
              "time " + config::excerpt(cell) +
                  " s does not increase (previous row: " + std::to_string(r.t.back()) + " s)");
        r.t.push_back(v);
      } else {
        columns[c]->push_back(v);
      }
    }
  }
  if (header.empty()) throw RecordingError(file, line_no, "no header line (an empty file?)");
  if (r.t.size() < min_rows)
    throw RecordingError(file, line_no,
                         "too short: " + std::to_string(r.t.size()) + " rows, at least " +
                             std::to_string(min_rows) + " are needed");
  return r;
}

Recording load_recording(const std::string& path, std::size_t min_rows) {
  // The checks of every input (no FIFO, no directory, the reason when missing); no size cap.
  return parse_recording(config::read_input_file(path, SIZE_MAX), path, min_rows);
}

}  // namespace planter::analysis
