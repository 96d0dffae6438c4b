#pragma once
// The figures of one run, accumulated tick by tick, and summary.json.
#include <cstdint>
#include <string>
#include <vector>

#include "firmware/controller/telemetry.h"
#include "sim/plant/plant.h"
#include "sim/runner/loop_scores.h"

namespace planter::sim {

struct Summary {
  std::string scenario;
  // The board whose settings ran, and whether it is a machine's (its CAN interface a real one:
  // its bus and lines are not used here, only its settings; issue 54).
  std::string board;
  bool board_is_hardware = false;
  double sigma_target = 1.5;
  double sigma_true_mean = 0, sigma_true_rms_error_pct = 0, sigma_ctrl_rms_error_pct = 0;
  double uprightness_pct = 0, damage_pct = 0;
  int seedlings_lodged = 0;  // lying in the furrow (tilt 90 deg)
  // In the clamp (sim/plant/seedling_release.h): dropped in the carry (a skip), slid along the
  // clamp by more than 5 mm, turned in it by more than 5 deg.
  int seedlings_fell_in_carry = 0, seedlings_slid_in_clamp = 0, seedlings_turned_in_clamp = 0;
  // The damaged seedlings' strengths against the measured peaks' range (127.2-191.6 N).
  double damaged_strength_mean_N = 0;
  int damaged_below_measured = 0;
  double spacing_mean_mm = 0, spacing_cv_pct = 0;
  double clamp_force_mean_N = 0, clamp_force_max_N = 0, clamp_ceiling_N = 0;
  double seedling_peak_force_mean_N = 0;
  double depth_mean_mm = 0, depth_rms_error_mm = 0, depth_target_mm = 0;
  int seedlings_planted = 0, seedlings_damaged = 0;
  std::vector<int> plot_counts;
  // The planting monitor as the controller saw it through the photo-eye (when one is fitted),
  // and its rules applied to the seedlings the simulator planted: the ground truth.
  bool monitor_fitted = false;
  PlantingFigures monitor;
  int truth_skips = 0, truth_multiples = 0;
  std::uint32_t warnings_seen = 0;  // warning:: bits that held at some tick
  LoopScores loops;                 // each loop against its goal (loop_scores.h)
  double distance_m = 0;
  double sim_seconds = 0, wall_seconds = 0, realtime_factor = 0;
  double can_bus_load_pct = 0;
  std::uint64_t can_frames = 0;
  std::uint32_t faults = 0;
  std::string final_state;
  bool route_complete = true;
  // What a reader must know beyond the figures (a route cut short, ...).
  std::vector<std::string> notes;
  // The model assumptions of the run, from its configuration (model_assumptions.h).
  std::vector<std::string> assumptions;

  [[nodiscard]] std::string to_json() const;
  // summary.json read back (what a plan's run wrote): every field to_json writes.
  // Throws nlohmann::json::exception.
  static Summary from_json(const std::string& text);
};

class SummaryBuilder {
 public:
  void configure(double sigma, double depth_target_mm, double ceiling_N, double settle_s,
                 const PlantingMonitorConfig& monitor) {
    monitor_cfg_ = monitor;
    sigma_ = sigma;
    depth_target_ = depth_target_mm;
    ceiling_ = ceiling_N;
    settle_s_ = settle_s;
  }
  void add(const Telemetry& c, const PlantTruth& truth, bool running, double running_for_s);
  Summary finish(const SeedlingProcess& seedlings, double plot_length_m, int plots) const;

 private:
  double sigma_ = 1.5, depth_target_ = 102.0, ceiling_ = 120.0, settle_s_ = 8.0;
  double sigma_true_sum_ = 0, sigma_true_err2_ = 0, sigma_ctrl_err2_ = 0;
  std::uint64_t sigma_n_ = 0, sigma_ctrl_n_ = 0;
  double force_sum_ = 0, force_max_ = 0;
  std::uint64_t force_n_ = 0;
  double depth_sum_ = 0, depth_err2_ = 0;
  std::uint64_t depth_n_ = 0;
  PlantingMonitorConfig monitor_cfg_;
  PlantingFigures monitor_;
  std::uint32_t warnings_seen_ = 0;
};

}  // namespace planter::sim
