#include "sim/runner/recording_writer.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "config/recording_format.h"
#include "sim/plant/truth_columns.h"

namespace planter::sim {

RecordingWriter::RecordingWriter(const std::string& path, const std::string& shown_path,
                                 const std::vector<std::pair<std::string, std::string>>& metadata)
    : path_(shown_path) {
  // Created, never replaced: a recording that exists is not overwritten (issue 28, item 7).
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  file_ = fd >= 0 ? ::fdopen(fd, "w") : nullptr;
  if (fd >= 0 && file_ == nullptr) ::close(fd);
  if (file_ == nullptr) {
    throw std::runtime_error(path_ + ": cannot be written: " + std::strerror(errno));
  }
  for (const auto& [k, v] : metadata) std::fprintf(file_, "# %s: %s\n", k.c_str(), v.c_str());
  std::fprintf(file_, "%s,%s\n", config::controller_columns().c_str(), truth_header().c_str());
}

RecordingWriter::~RecordingWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

void RecordingWriter::write(const TickRecord& r) {
  const PlantTruth& p = r.truth;
  char row[2048];
  const double t_s = static_cast<double>(r.controller.time_ns) * 1e-9;
  const int n = config::format_controller_columns(row, sizeof row, t_s, r.controller);
  config::RowText line(row, sizeof row, n > 0 ? static_cast<std::size_t>(n) : 0);
  // The sensor path's rows ago (the first row's before there were that many).
  recent_[rows_ % recent_.size()] = p;
  const PlantTruth& sensed =
      recent_[(rows_ >= kSensorPathTicks ? rows_ - kSensorPathTicks : 0) % recent_.size()];
  ++rows_;
  for (const TruthColumn& c : kTruthColumns) {
    line.separator();
    line.fixed((c.through_sensor_path ? sensed : p).*c.value, c.decimals);
  }
  line.text("\n");
  // A row cut short would be a wrong row: refuse it instead.
  if (n <= 0 || line.length() >= sizeof row)
    throw std::runtime_error(path_ + ": the row at " + std::to_string(t_s) +
                             " s does not fit a line of 2 kB");
  std::fwrite(row, 1, line.length(), file_);
}

bool RecordingWriter::flush() {
  return file_ != nullptr && std::fflush(file_) == 0 && std::ferror(file_) == 0;
}

void RecordingWriter::close() {
  if (file_ == nullptr) return;
  const bool failed = std::fflush(file_) != 0 || std::ferror(file_) != 0;
  const int err = errno;
  const int rc = std::fclose(file_);
  file_ = nullptr;
  if (failed || rc != 0) {
    throw std::runtime_error(path_ + ": cannot be written: " + std::strerror(failed ? err : errno));
  }
}

void ReportSeries::add(const TickRecord& r) {
  const Telemetry& c = r.controller;
  const PlantTruth& p = r.truth;
  t.push_back(static_cast<double>(c.time_ns) * 1e-9);
  v_ground.push_back(p.v_mps);
  v_wheel.push_back(c.v_wheel_mps);
  // Undefined at a stop: NaN, drawn as a gap.
  sigma_true.push_back(p.v_mps >= kSigmaMinSpeedMps ? p.sigma : std::nan(""));
  sigma_ctrl.push_back(c.v_wheel_mps >= kSigmaMinSpeedMps ? c.sigma : std::nan(""));
  omega.push_back(c.omega_radps);
  omega_cmd.push_back(c.omega_cmd_radps);
  clamp_force.push_back(p.clamp_force_N);
  clamp_force_cmd.push_back(c.clamp_force_cmd_N);
  depth.push_back(p.depth_mm);
  depth_cmd.push_back(c.depth_cmd_mm);
}

}  // namespace planter::sim
