#include "sim/runner/summary.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "config/stem_strength.h"

namespace planter::sim {

void SummaryBuilder::add(const Telemetry& c, const PlantTruth& t, bool running,
                         double running_for_s) {
  monitor_ = c.planting;
  warnings_seen_ |= c.warnings;
  if (!running) return;
  if (t.v_mps >= kSigmaMinSpeedMps) {
    sigma_true_sum_ += t.sigma;
    sigma_true_err2_ += std::pow((t.sigma - sigma_) / sigma_, 2);
    ++sigma_n_;
  }
  if (c.v_wheel_mps >= kSigmaMinSpeedMps) {
    sigma_ctrl_err2_ += std::pow((c.sigma - sigma_) / sigma_, 2);
    ++sigma_ctrl_n_;
  }
  force_max_ = std::max(force_max_, t.clamp_force_N);
  if (running_for_s > settle_s_) {
    force_sum_ += t.clamp_force_N;
    ++force_n_;
    depth_sum_ += t.depth_mm;
    depth_err2_ += std::pow(t.depth_mm - depth_target_, 2);
    ++depth_n_;
  }
}

Summary SummaryBuilder::finish(const SeedlingProcess& process, double plot_length_m,
                               int plots) const {
  Summary s;
  s.sigma_target = sigma_;
  s.depth_target_mm = depth_target_;
  s.clamp_ceiling_N = ceiling_;
  s.sigma_true_mean = sigma_n_ ? sigma_true_sum_ / static_cast<double>(sigma_n_) : 0.0;
  s.sigma_true_rms_error_pct =
      sigma_n_ ? 100.0 * std::sqrt(sigma_true_err2_ / static_cast<double>(sigma_n_)) : 0.0;
  s.sigma_ctrl_rms_error_pct =
      sigma_ctrl_n_ ? 100.0 * std::sqrt(sigma_ctrl_err2_ / static_cast<double>(sigma_ctrl_n_))
                    : 0.0;
  s.clamp_force_mean_N = force_n_ ? force_sum_ / static_cast<double>(force_n_) : 0.0;
  s.clamp_force_max_N = force_max_;
  s.depth_mean_mm = depth_n_ ? depth_sum_ / static_cast<double>(depth_n_) : 0.0;
  s.depth_rms_error_mm = depth_n_ ? std::sqrt(depth_err2_ / static_cast<double>(depth_n_)) : 0.0;

  std::vector<double> xs;
  double upright_sum = 0, peak_sum = 0, damaged_strength_sum = 0;
  const double weakest_measured_N = config::measured_strength().min_N;
  for (std::size_t i = 0; i < process.released(); ++i) {
    const Seedling& sd = process.seedlings()[i];
    if (sd.release.fell_in_carry) ++s.seedlings_fell_in_carry;
    if (!sd.planted) continue;
    if (std::abs(sd.release.clamp_slip_mm) > 5.0) ++s.seedlings_slid_in_clamp;
    if (std::abs(sd.release.clamp_turn_deg) > 5.0) ++s.seedlings_turned_in_clamp;
    if (sd.damaged) {
      damaged_strength_sum += sd.strength_N;
      if (sd.strength_N < weakest_measured_N) ++s.damaged_below_measured;
    }
    xs.push_back(sd.x_m);
    upright_sum += std::max(0.0, 1.0 - std::abs(sd.tilt_deg) / 90.0);
    peak_sum += sd.peak_force_N;
    if (sd.damaged) ++s.seedlings_damaged;
    if (sd.release.lodged) ++s.seedlings_lodged;
  }
  s.seedlings_planted = static_cast<int>(xs.size());
  if (s.seedlings_damaged > 0)
    s.damaged_strength_mean_N = damaged_strength_sum / s.seedlings_damaged;
  if (!xs.empty()) {
    s.uprightness_pct = 100.0 * upright_sum / static_cast<double>(xs.size());
    s.damage_pct = 100.0 * s.seedlings_damaged / static_cast<double>(xs.size());
    s.seedling_peak_force_mean_N = peak_sum / static_cast<double>(xs.size());
  }
  std::sort(xs.begin(), xs.end());
  std::vector<double> gaps;
  for (std::size_t i = 1; i < xs.size(); ++i) gaps.push_back((xs[i] - xs[i - 1]) * 1000.0);
  if (!gaps.empty()) {
    double sum = 0, sum2 = 0;
    for (double g : gaps) sum += g;
    s.spacing_mean_mm = sum / static_cast<double>(gaps.size());
    for (double g : gaps) sum2 += (g - s.spacing_mean_mm) * (g - s.spacing_mean_mm);
    s.spacing_cv_pct =
        100.0 * std::sqrt(sum2 / static_cast<double>(gaps.size())) / s.spacing_mean_mm;
  }
  s.monitor_fitted = monitor_cfg_.sensor_fitted;
  s.monitor = monitor_;
  s.warnings_seen = warnings_seen_;
  for (double g : gaps) {
    if (monitor_cfg_.is_skip(g)) ++s.truth_skips;
    if (monitor_cfg_.is_multiple(g)) ++s.truth_multiples;
  }
  s.plot_counts.assign(static_cast<std::size_t>(plots), 0);
  for (double x : xs) {
    const auto plot = static_cast<int>(x / plot_length_m);
    if (plot >= 0 && plot < plots) ++s.plot_counts[static_cast<std::size_t>(plot)];
  }
  return s;
}

std::string Summary::to_json() const {
  nlohmann::ordered_json j;
  j["scenario"] = scenario;
  j["board"] = board;
  j["board_is_hardware"] = board_is_hardware;
  j["sigma_target"] = sigma_target;
  j["sigma_true_mean"] = sigma_true_mean;
  j["sigma_true_rms_error_pct"] = sigma_true_rms_error_pct;
  j["sigma_ctrl_rms_error_pct"] = sigma_ctrl_rms_error_pct;
  j["uprightness_pct"] = uprightness_pct;
  j["seedlings_lodged"] = seedlings_lodged;
  j["seedlings_fell_in_carry"] = seedlings_fell_in_carry;
  j["seedlings_slid_in_clamp"] = seedlings_slid_in_clamp;
  j["seedlings_turned_in_clamp"] = seedlings_turned_in_clamp;
  j["damaged_strength_mean_N"] = damaged_strength_mean_N;
  j["damaged_below_weakest_measured"] = damaged_below_measured;
  j["damage_pct"] = damage_pct;
  j["damage_seen"] = monitor.damage_seen;  // by the clamp's reading, photo-eye or not
  j["spacing_mean_mm"] = spacing_mean_mm;
  j["spacing_cv_pct"] = spacing_cv_pct;
  if (monitor_fitted) {
    // What the controller's planting monitor counted through the photo-eye, and the truth.
    j["monitor"] = {{"seedlings", monitor.seedlings},
                    {"spacings", monitor.spacings},
                    {"spacing_mean_mm", monitor.spacing_mean_mm},
                    {"spacing_cv", monitor.spacing_cv},
                    {"skips", monitor.skips},
                    {"multiples", monitor.multiples},
                    {"singulation_pct", monitor.singulation_pct},
                    {"empty_belt_warned", (warnings_seen & warning::kEmptyBelt) != 0},
                    {"truth_skips", truth_skips},
                    {"truth_multiples", truth_multiples}};
  }
  j["clamp_force_mean_N"] = clamp_force_mean_N;
  j["clamp_force_max_N"] = clamp_force_max_N;
  j["clamp_ceiling_N"] = clamp_ceiling_N;
  j["seedling_peak_force_mean_N"] = seedling_peak_force_mean_N;
  j["depth_mean_mm"] = depth_mean_mm;
  j["depth_rms_error_mm"] = depth_rms_error_mm;
  j["depth_target_mm"] = depth_target_mm;
  j["seedlings_planted"] = seedlings_planted;
  j["seedlings_damaged"] = seedlings_damaged;
  j["plot_counts"] = plot_counts;
  j["distance_m"] = distance_m;
  j["route_complete"] = route_complete;
  j["notes"] = notes;
  j["assumptions"] = assumptions;
  j["sim_seconds"] = sim_seconds;
  j["wall_seconds"] = wall_seconds;
  j["realtime_factor"] = realtime_factor;
  j["can_bus_load_pct"] = can_bus_load_pct;
  j["can_frames"] = can_frames;
  j["faults"] = faults;
  j["final_state"] = final_state;
  j["warnings_seen"] = warnings_seen;
  j["loops"] = nlohmann::ordered_json::parse(loop_scores_json(loops));
  return j.dump(2);
}

Summary Summary::from_json(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  Summary s;
  s.scenario = j.at("scenario").get<std::string>();
  s.board = j.value("board", std::string());  // summaries written before it was kept
  s.board_is_hardware = j.value("board_is_hardware", false);
  s.sigma_target = j.at("sigma_target").get<double>();
  s.sigma_true_mean = j.at("sigma_true_mean").get<double>();
  s.sigma_true_rms_error_pct = j.at("sigma_true_rms_error_pct").get<double>();
  s.sigma_ctrl_rms_error_pct = j.at("sigma_ctrl_rms_error_pct").get<double>();
  s.uprightness_pct = j.at("uprightness_pct").get<double>();
  s.seedlings_lodged = j.at("seedlings_lodged").get<int>();
  s.seedlings_fell_in_carry = j.at("seedlings_fell_in_carry").get<int>();
  s.seedlings_slid_in_clamp = j.at("seedlings_slid_in_clamp").get<int>();
  s.seedlings_turned_in_clamp = j.at("seedlings_turned_in_clamp").get<int>();
  s.damaged_strength_mean_N = j.at("damaged_strength_mean_N").get<double>();
  s.damaged_below_measured = j.at("damaged_below_weakest_measured").get<int>();
  s.damage_pct = j.at("damage_pct").get<double>();
  s.monitor.damage_seen = j.at("damage_seen").get<double>();
  s.spacing_mean_mm = j.at("spacing_mean_mm").get<double>();
  s.spacing_cv_pct = j.at("spacing_cv_pct").get<double>();
  if (j.contains("monitor")) {
    const auto& m = j.at("monitor");
    s.monitor_fitted = true;
    s.monitor.seedlings = m.at("seedlings").get<double>();
    s.monitor.spacings = m.at("spacings").get<double>();
    s.monitor.spacing_mean_mm = m.at("spacing_mean_mm").get<double>();
    s.monitor.spacing_cv = m.at("spacing_cv").get<double>();
    s.monitor.skips = m.at("skips").get<double>();
    s.monitor.multiples = m.at("multiples").get<double>();
    s.monitor.singulation_pct = m.at("singulation_pct").get<double>();
    s.truth_skips = m.at("truth_skips").get<int>();
    s.truth_multiples = m.at("truth_multiples").get<int>();
  }
  s.clamp_force_mean_N = j.at("clamp_force_mean_N").get<double>();
  s.clamp_force_max_N = j.at("clamp_force_max_N").get<double>();
  s.clamp_ceiling_N = j.at("clamp_ceiling_N").get<double>();
  s.seedling_peak_force_mean_N = j.at("seedling_peak_force_mean_N").get<double>();
  s.depth_mean_mm = j.at("depth_mean_mm").get<double>();
  s.depth_rms_error_mm = j.at("depth_rms_error_mm").get<double>();
  s.depth_target_mm = j.at("depth_target_mm").get<double>();
  s.seedlings_planted = j.at("seedlings_planted").get<int>();
  s.seedlings_damaged = j.at("seedlings_damaged").get<int>();
  s.plot_counts = j.at("plot_counts").get<std::vector<int>>();
  s.distance_m = j.at("distance_m").get<double>();
  s.route_complete = j.at("route_complete").get<bool>();
  s.notes = j.at("notes").get<std::vector<std::string>>();
  s.assumptions = j.at("assumptions").get<std::vector<std::string>>();
  s.sim_seconds = j.at("sim_seconds").get<double>();
  s.wall_seconds = j.at("wall_seconds").get<double>();
  s.realtime_factor = j.at("realtime_factor").get<double>();
  s.can_bus_load_pct = j.at("can_bus_load_pct").get<double>();
  s.can_frames = j.at("can_frames").get<std::uint64_t>();
  s.faults = j.at("faults").get<std::uint32_t>();
  s.final_state = j.at("final_state").get<std::string>();
  s.warnings_seen = j.at("warnings_seen").get<std::uint32_t>();
  s.loops = loop_scores_from_json(j.at("loops").dump());
  return s;
}

}  // namespace planter::sim
