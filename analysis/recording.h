#pragma once
// A recording in the recording format (docs/recording-format.md), as the analysis reads it: `#`
// metadata lines, a header of signal names, one row per sample, time strictly increasing. Columns
// may be absent; `state` is kept as text. Every defect is one RecordingError with its line.
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace planter::analysis {

class RecordingError : public std::runtime_error {
 public:
  // Line 0: about the file as a whole (no line to name).
  RecordingError(const std::string& file, int line, const std::string& what)
      : std::runtime_error(message(file, line, what)), line_(line) {}
  [[nodiscard]] int line() const { return line_; }

 private:
  static std::string message(const std::string& file, int line, const std::string& what) {
    std::string m = file;
    if (line > 0) m.append(":").append(std::to_string(line));
    return m.append(": ").append(what);
  }
  int line_;
};

struct Recording {
  std::string file;
  std::map<std::string, std::string> metadata;
  std::vector<double> t;
  std::map<std::string, std::vector<double>> signals;  // numeric columns by name
  std::vector<std::string> state;                      // empty when there is no state column
  std::size_t decimation_stride = 1;  // rows of the recording per row here (decimation.h)
  // Each low-pass filtered column's white noise, measured at the recording's own rate before
  // decimation (after it, the filter has coloured the noise and second differences miss most).
  std::map<std::string, double> full_rate_noise;
  // Each low-pass filtered column's value grid (a quantised sensor's step: value_grid()), found
  // before decimation: the filtered averages fill the grid in.
  std::map<std::string, double> full_rate_grid;
  // Each low-pass filtered column's count of rows holding its largest value exactly, before the
  // filter rings at a flat top's edges: a saturating sensor records its limit over and over.
  std::map<std::string, std::size_t> full_rate_top_rows;
  // A thinned recording's displacement columns (a channel's displacement()) at the recording's
  // own rate, unfiltered: decimation_stride rows for each row here. A rate-independent effect
  // runs on this path and is then filtered and thinned as the recorded output was
  // (decimation.h). Run on the filtered column, it saw the filter's ringing at each move's ends:
  // on the outside generator's clamp the roller reversed 3507 times where it had 42, each
  // reversal reset the Bouc-Wen state part way, and the hysteresis height read 4-5 % high.
  std::map<std::string, std::vector<double>> travel;
  [[nodiscard]] bool has(const std::string& name) const { return signals.count(name) != 0; }
  [[nodiscard]] const std::vector<double>& at(const std::string& name) const {
    return signals.at(name);
  }
  [[nodiscard]] std::size_t size() const { return t.size(); }
  // The board's SYNC period the recording declares (sync_period_s), or 0 when it declares none.
  [[nodiscard]] double sync_period_s() const;
};

// Reads a recording a block of rows at a time, so that a recording of any length can be
// analysed in windows with bounded memory. The metadata and the header are read on opening.
// A recording's file, metadata, stride and full-rate figures, without its rows: what every
// derived recording (first_rows, decimated) keeps.
Recording without_rows(const Recording& r);
// The first `rows` rows of a recording, everything else about it kept.
Recording first_rows(const Recording& r, std::size_t rows);

class RecordingReader {
 public:
  // From a file (checked as every input: no FIFO, no directory; a byte-order mark skipped).
  explicit RecordingReader(const std::string& path);
  // From text already in memory; `file` names the messages.
  RecordingReader(const std::string& text, const std::string& file);
  ~RecordingReader();
  RecordingReader(const RecordingReader&) = delete;
  RecordingReader& operator=(const RecordingReader&) = delete;

  // Only these columns are kept (besides t); every row is still checked for its cell count,
  // and a kept cell for being a number. Empty: all columns, and the state.
  void keep_only(const std::vector<std::string>& columns);
  // Starts `out` afresh (file, metadata, the kept columns) and reads up to max_rows rows into
  // it. Returns the rows read: fewer than max_rows only at the end of the file.
  std::size_t read(Recording& out, std::size_t max_rows);
  [[nodiscard]] bool at_end() const { return at_end_; }
  // Whether anything follows what has been read (a trailing blank line counts).
  [[nodiscard]] bool more() const;
  [[nodiscard]] int line() const { return line_no_; }
  [[nodiscard]] const std::vector<std::string>& header() const { return header_; }
  // Throws "too short" at the line reached unless `r` has at least min_rows rows.
  void require_rows(const Recording& r, std::size_t min_rows) const;

 private:
  void read_header();
  void check_sync_period(const std::string& value) const;
  bool next_line(std::string& line);

  std::string file_;
  struct Source;
  // Owned here so a constructor that throws (a bad header) still frees it.
  std::unique_ptr<Source> source_;
  std::map<std::string, std::string> metadata_;
  std::vector<std::string> header_;
  std::vector<bool> kept_;
  bool keep_state_ = true;
  int t_col_ = -1, state_col_ = -1;
  int line_no_ = 0;
  bool at_end_ = false;
  double last_t_ = 0.0;
  bool any_row_ = false;
};

// Parses CSV text (file names the messages). Needs at least `min_rows` rows.
Recording parse_recording(const std::string& text, const std::string& file,
                          std::size_t min_rows = 50);
// Reads and parses a file.
Recording load_recording(const std::string& path, std::size_t min_rows = 50);

}  // namespace planter::analysis
