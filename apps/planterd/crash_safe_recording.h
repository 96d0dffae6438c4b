#pragma once
// planterd's telemetry recording (docs/recording-format.md) written so that a kill -9 or a power
// cut loses at most the rows of the last unflushed block:
// - rows are formatted off the real-time thread and appended in blocks that end on a row
//   boundary, each with one write() followed by fdatasync();
// - a file left by an earlier run is never overwritten: its torn tail (if the power went
//   mid-block) is cut back to the last complete row and it is moved to FILE.N;
// - so a reader sees complete rows only, and the loss is bounded by one flush interval.
#include <cstdint>
#include <string>
#include <vector>

#include "firmware/controller/telemetry.h"

namespace planter::daemon {

// Cuts a recording back to its last complete line. Returns the bytes removed (0 if none).
// Throws std::runtime_error when the file cannot be read or truncated.
std::uint64_t repair_torn_tail(const std::string& path);

class CrashSafeRecording {
 public:
  // Moves an existing file aside (repaired) and starts a new one with metadata and header.
  // Throws std::runtime_error when it cannot.
  CrashSafeRecording(const std::string& path, const std::vector<std::string>& metadata);
  ~CrashSafeRecording();
  CrashSafeRecording(const CrashSafeRecording&) = delete;
  CrashSafeRecording& operator=(const CrashSafeRecording&) = delete;

  // Formats one row into the pending block (not the real-time thread). False (and counted)
  // when the row does not fit a line of 2 kB: it is not recorded, and the caller says so.
  bool add(double t_s, const Telemetry& row);
  // Writes the pending block and syncs it. Returns false (and keeps the block) on failure.
  bool flush();

  [[nodiscard]] const std::string& moved_aside_to() const { return moved_aside_; }
  [[nodiscard]] std::uint64_t rows_written() const { return rows_written_; }
  [[nodiscard]] std::uint64_t blocks_written() const { return blocks_written_; }
  [[nodiscard]] std::uint64_t rows_unformatted() const { return rows_unformatted_; }

 private:
  int fd_ = -1;
  std::string path_;
  std::string moved_aside_;
  std::string block_;
  std::uint64_t rows_pending_ = 0;
  std::uint64_t rows_written_ = 0;
  std::uint64_t blocks_written_ = 0;
  std::uint64_t rows_unformatted_ = 0;
};

}  // namespace planter::daemon
