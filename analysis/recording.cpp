#include "analysis/recording.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <type_traits>

#include "config/config_key.h"
#include "config/input_file.h"
#include "config/recording_format.h"

namespace planter::analysis {
namespace {

constexpr std::size_t kMaxLineBytes = 1u << 20;  // 1 MB
constexpr std::size_t kMaxColumns = 4096;

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

struct RecordingReader::Source {
  std::ifstream file;
  std::istringstream text;
  std::istream* in = nullptr;
};

RecordingReader::RecordingReader(const std::string& path)
    : file_(path), source_(std::make_unique<Source>()) {
  config::require_regular_file(path);
  source_->file.open(path, std::ios::binary);
  if (!source_->file) throw RecordingError(path, 0, "cannot be opened");
  source_->in = &source_->file;
  read_header();
}

RecordingReader::RecordingReader(const std::string& text, const std::string& file)
    : file_(file), source_(std::make_unique<Source>()) {
  source_->text.str(text);
  source_->in = &source_->text;
  read_header();
}

RecordingReader::~RecordingReader() = default;

bool RecordingReader::more() const {
  return !at_end_ && source_->in->peek() != std::char_traits<char>::eof();
}

bool RecordingReader::next_line(std::string& line) {
  // Read in pieces, so a line without end cannot take the memory (issue 28, item 14: a 1 GB
  // line took 2-3 GB before it was refused).
  std::istream& in = *source_->in;
  line.clear();
  char piece[8192];
  bool any = false;
  for (;;) {
    in.getline(piece, sizeof piece);
    if (in.bad()) throw RecordingError(file_, line_no_ + 1, "cannot be read");
    const auto n = static_cast<std::size_t>(in.gcount());
    any = any || n > 0;
    if (in.eof()) {  // the last line, with no newline after it
      line.append(piece, n);
      break;
    }
    if (in.fail()) {  // the piece filled before the newline
      line.append(piece, n);
      in.clear();
      if (line.size() > kMaxLineBytes)
        throw RecordingError(file_, line_no_ + 1,
                             "a line longer than " + std::to_string(kMaxLineBytes >> 20) +
                                 " MB (a recording's rows are a few hundred bytes)");
      continue;
    }
    line.append(piece, n - 1);  // the newline was taken and counted
    break;
  }
  if (!any) return false;
  ++line_no_;
  // A CSV saved on Windows may start with a UTF-8 byte-order mark: it is not part of "t".
  if (line_no_ == 1) config::strip_utf8_bom(line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

// The one metadata value planter-fit uses: a wrong one would shift the drives' commands.
void RecordingReader::check_sync_period(const std::string& value) const {
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(v) || v <= 0.0 ||
      v > config::kSyncPeriodMaxS)
    throw RecordingError(file_, line_no_,
                         "metadata " + std::string(config::kSyncPeriodKey) + ": '" + value +
                             "' must be the SYNC period in seconds, in (0, " +
                             config::number_text(config::kSyncPeriodMaxS) + "]");
}

double Recording::sync_period_s() const {
  const auto it = metadata.find(std::string(config::kSyncPeriodKey));
  return it == metadata.end() ? 0.0 : std::strtod(it->second.c_str(), nullptr);
}

Recording without_rows(const Recording& r) {
  Recording out;
  out.file = r.file;
  out.metadata = r.metadata;
  out.decimation_stride = r.decimation_stride;
  out.full_rate_noise = r.full_rate_noise;
  out.full_rate_grid = r.full_rate_grid;
  out.full_rate_top_rows = r.full_rate_top_rows;
  return out;
}

Recording first_rows(const Recording& r, std::size_t rows) {
  rows = std::min(rows, r.size());
  Recording out = without_rows(r);
  const auto first = [rows](const auto& v) {
    using V = std::decay_t<decltype(v)>;
    return V(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(std::min(rows, v.size())));
  };
  out.t = first(r.t);
  out.state = first(r.state);
  for (const auto& [name, v] : r.signals) out.signals.emplace(name, first(v));
  for (const auto& [name, v] : r.travel) {
    const std::size_t full = std::min(v.size(), rows * r.decimation_stride);
    out.travel.emplace(
        name, std::vector<double>(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(full)));
  }
  return out;
}

void RecordingReader::read_header() {
  std::string line;
  while (next_line(line)) {
    if (line.empty()) continue;
    if (line[0] == '#') {
      const auto colon = line.find(':');
      if (colon != std::string::npos) {
        const std::string key = trim(line.substr(1, colon - 1));
        const std::string value = trim(line.substr(colon + 1));
        if (key == config::kSyncPeriodKey) check_sync_period(value);
        metadata_[key] = value;
      }
      continue;
    }
    header_ = split_commas(line);
    if (header_.size() > kMaxColumns)
      throw RecordingError(file_, line_no_,
                           "header: " + std::to_string(header_.size()) + " columns, at most " +
                               std::to_string(kMaxColumns));
    std::set<std::string> seen;
    for (std::size_t c = 0; c < header_.size(); ++c) {
      header_[c] = trim(header_[c]);
      const std::string& name = header_[c];
      if (name.empty())
        throw RecordingError(file_, line_no_,
                             "header: column " + std::to_string(c + 1) + " has no name");
      if (!seen.insert(name).second)
        throw RecordingError(file_, line_no_,
                             "header: column '" + config::excerpt(name) + "' appears twice");
      if (name == "t") t_col_ = static_cast<int>(c);
      if (name == "state") state_col_ = static_cast<int>(c);
    }
    if (t_col_ < 0)
      throw RecordingError(file_, line_no_,
                           "header: no 't' column (the first line after the # comments must "
                           "be the header of signal names, with t in seconds)");
    kept_.assign(header_.size(), true);
    return;
  }
  throw RecordingError(file_, line_no_, "no header line (an empty file?)");
}

void RecordingReader::keep_only(const std::vector<std::string>& columns) {
  if (columns.empty()) {
    kept_.assign(header_.size(), true);
    keep_state_ = true;
    return;
  }
  for (std::size_t c = 0; c < header_.size(); ++c)
    kept_[c] = std::find(columns.begin(), columns.end(), header_[c]) != columns.end();
  keep_state_ = std::find(columns.begin(), columns.end(), "state") != columns.end();
}

std::size_t RecordingReader::read(Recording& r, std::size_t max_rows) {
  r = Recording{};
  r.file = file_;
  r.metadata = metadata_;
  std::vector<std::vector<double>*> columns(header_.size(), nullptr);
  for (std::size_t c = 0; c < header_.size(); ++c)
    if (kept_[c] && static_cast<int>(c) != state_col_ && static_cast<int>(c) != t_col_)
      columns[c] = &r.signals[header_[c]];
  std::string line;
  std::size_t rows = 0;
  while (rows < max_rows) {
    if (!next_line(line)) {
      at_end_ = true;
      break;
    }
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_commas(line);
    if (cells.size() != header_.size())
      throw RecordingError(file_, line_no_,
                           std::to_string(cells.size()) + " cells, the header has " +
                               std::to_string(header_.size()));
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (static_cast<int>(c) == state_col_) {
        if (keep_state_) r.state.push_back(trim(cells[c]));
        continue;
      }
      if (columns[c] == nullptr && static_cast<int>(c) != t_col_) continue;
      const std::string cell = trim(cells[c]);
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(cell.c_str(), &end);
      // ERANGE with a tiny result is underflow (1e-310 reads as a denormal or 0: a number).
      const bool overflow = errno == ERANGE && std::fabs(v) == HUGE_VAL;
      if (cell.empty() || end != cell.c_str() + cell.size() || overflow)
        throw RecordingError(file_, line_no_,
                             "column '" + config::excerpt(header_[c]) + "': '" +
                                 config::excerpt(cell) + "' is not a number");
      if (!std::isfinite(v))
        throw RecordingError(file_, line_no_,
                             "column '" + config::excerpt(header_[c]) +
                                 "': " + config::excerpt(cell) +
                                 " (NaN or infinite values are not allowed)");
      if (static_cast<int>(c) == t_col_) {
        if (any_row_ && v <= last_t_)
          throw RecordingError(
              file_, line_no_,
              "time " + config::excerpt(cell) +
                  " s does not increase (previous row: " + std::to_string(last_t_) + " s)");
        last_t_ = v;
        any_row_ = true;
        r.t.push_back(v);
      } else {
        columns[c]->push_back(v);
      }
    }
    ++rows;
  }
  return rows;
}

void RecordingReader::require_rows(const Recording& r, std::size_t min_rows) const {
  if (r.t.size() < min_rows)
    throw RecordingError(file_, line_no_,
                         "too short: " + std::to_string(r.t.size()) + " rows, at least " +
                             std::to_string(min_rows) + " are needed");
}

Recording parse_recording(const std::string& text, const std::string& file, std::size_t min_rows) {
  RecordingReader reader(text, file);
  Recording r;
  reader.read(r, SIZE_MAX);
  reader.require_rows(r, min_rows);
  return r;
}

Recording load_recording(const std::string& path, std::size_t min_rows) {
  // The checks of every input (no FIFO, no directory, the reason when missing); no size cap.
  RecordingReader reader(path);
  Recording r;
  reader.read(r, SIZE_MAX);
  reader.require_rows(r, min_rows);
  return r;
}

}  // namespace planter::analysis
