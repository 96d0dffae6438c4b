#include "sim/runner/recording_writer.h"

#include <stdexcept>

namespace planter::sim {

RecordingWriter::RecordingWriter(const std::string& path,
                                 const std::vector<std::pair<std::string, std::string>>& metadata)
    : file_(std::fopen(path.c_str(), "w")), path_(path) {
  if (file_ == nullptr) throw std::runtime_error(path + ": cannot open for writing");
  for (const auto& [k, v] : metadata) std::fprintf(file_, "# %s: %s\n", k.c_str(), v.c_str());
  std::fprintf(file_,
               "t,v_ground,wheel_counts,v_wheel,omega_cmd,omega,disc_angle,disc_torque,sigma,clamp_"
               "force_cmd,"
               "clamp_pos_mm,clamp_force,depth_cmd_mm,depth_mm,depth_force,state,"
               "true_x_m,true_sigma,true_omega,true_clamp_force,true_depth_mm,true_slip\n");
}

RecordingWriter::~RecordingWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

void RecordingWriter::write(const TickRecord& r) {
  const Telemetry& c = r.controller;
  const PlantTruth& p = r.truth;
  std::fprintf(file_,
               "%.3f,%.5f,%lld,%.5f,%.5f,%.5f,%.5f,%.4f,%.4f,%.2f,%.4f,%.2f,%.3f,%.3f,%.2f,%s,%.5f,"
               "%.4f,%.5f,%.2f,%.3f,%.4f\n",
               static_cast<double>(c.time_ns) * 1e-9, p.v_mps,
               static_cast<long long>(c.wheel_counts), c.v_wheel_mps, c.omega_cmd_radps,
               c.omega_radps, c.disc_angle_rad, c.disc_torque_Nm, c.sigma, c.clamp_force_cmd_N,
               c.clamp_pos_mm, c.clamp_force_N, c.depth_cmd_mm, c.depth_mm, c.depth_force_N,
               supervisor_state_name(c.state), p.x_m, p.sigma, p.disc_omega_radps, p.clamp_force_N,
               p.depth_mm, p.slip);
}

void RecordingWriter::close() {
  if (file_ == nullptr) return;
  const bool failed = std::ferror(file_) != 0;
  const int rc = std::fclose(file_);
  file_ = nullptr;
  if (failed || rc != 0) throw std::runtime_error(path_ + ": write failed");
}

void ReportSeries::add(const TickRecord& r) {
  const Telemetry& c = r.controller;
  const PlantTruth& p = r.truth;
  t.push_back(static_cast<double>(c.time_ns) * 1e-9);
  v_ground.push_back(p.v_mps);
  v_wheel.push_back(c.v_wheel_mps);
  sigma_true.push_back(p.v_mps >= kSigmaMinSpeedMps ? p.sigma : 0.0);
  sigma_ctrl.push_back(c.v_wheel_mps >= kSigmaMinSpeedMps ? c.sigma : 0.0);
  omega.push_back(c.omega_radps);
  omega_cmd.push_back(c.omega_cmd_radps);
  clamp_force.push_back(p.clamp_force_N);
  clamp_force_cmd.push_back(c.clamp_force_cmd_N);
  depth.push_back(p.depth_mm);
  depth_cmd.push_back(c.depth_cmd_mm);
}

}  // namespace planter::sim
