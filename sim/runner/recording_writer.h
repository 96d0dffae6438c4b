#pragma once
// Writes the recording format (docs/recording-format.md): `#` metadata lines, a header, one row per
// tick. Columns prefixed `true_` are the simulator's ground truth (absent from field logs).
#include <array>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "sim/plant/truth_columns.h"
#include "sim/runner/lockstep_runner.h"

namespace planter::sim {

class RecordingWriter {
 public:
  // Throws std::runtime_error when the file cannot be written; messages name `shown_path`
  // (the path the user will see, when `path` is a staging file).
  RecordingWriter(const std::string& path, const std::string& shown_path,
                  const std::vector<std::pair<std::string, std::string>>& metadata);
  ~RecordingWriter();
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;
  void write(const TickRecord& row);
  // Hands what was written to the kernel; false when a write or the flush failed (a full disk).
  bool flush();
  // Flushes and closes; throws if anything failed to reach the disk.
  void close();

 private:
  std::FILE* file_;
  std::string path_;
  // The last rows' truth, for the columns written through the sensor path (truth_columns.h).
  std::array<PlantTruth, kSensorPathTicks + 1> recent_{};
  std::size_t rows_ = 0;
};

// Decimated series for the report's plots.
struct ReportSeries {
  std::vector<double> t, v_ground, v_wheel, sigma_true, sigma_ctrl, omega, omega_cmd;
  std::vector<double> clamp_force, clamp_force_cmd, depth, depth_cmd;
  void add(const TickRecord& row);
};

// The self-contained report.html; every user string in it is escaped. `map_html`, when not
// empty, is the as-planted map's section body (made by the caller, which places the seedlings).
std::string report_html(const Scenario& scenario, const Summary& summary,
                        const ReportSeries& series, const SeedlingProcess& seedlings,
                        const std::string& map_html = "");

}  // namespace planter::sim
