#pragma once
// The planting monitor: from the seedling photo-eye's beam breaks, each placed at the distance
// the soil wheel had travelled, the figures a planter monitor shows. Definitions after Kachman
// and Smith (1995, Trans. ASAE 38(2):379-387) and ISO 7256-1: a spacing over `skip_ratio` times
// the target is a skip, one of at most `multiple_ratio` times the target a multiple; singulation
// (their "quality of feed index") = 100 % - skips - multiples, as shares of all spacings.
// Spacings are counted only between seedlings planted in one stretch of running: a stop with
// planting off breaks the chain. No allocation; one update per tick.
#include <array>
#include <cstdint>

#include "firmware/io/process_image.h"

namespace planter {

struct PlantingMonitorConfig {
  bool sensor_fitted = false;       // the board wires a seedling photo-eye
  double clamp_pitch_mm = 44.25;    // clamps along the disc rim (the machine's)
  double target_spacing_mm = 29.5;  // clamp_pitch_mm / the sigma set-point (set by the loader)
  std::int64_t sensor_filter_ns = 20'000'000;  // beam breaks closer than this are one seedling
  double skip_ratio = 1.5;
  double multiple_ratio = 0.5;
  std::uint32_t empty_clamps_to_warn = 5;  // this many clamps passed empty in a row: an empty belt
  // What the operator's page shows beside the figures, as commercial planting monitors do: the
  // population from the row spacing, and an alarm past either limit.
  double row_spacing_mm = 900.0;        // the paper, Sec. 5: rows 90 cm apart at Zhangqiu
  double spacing_cv_alarm = 0.17;       // assumed (0.1-0.3): a CV above this is uneven spacing
  double singulation_alarm_pct = 95.0;  // assumed: singulation below this, skips or multiples

  // The one rule for a spacing (mm): the monitor's counts, the truth's and the as-planted map.
  [[nodiscard]] bool is_skip(double gap_mm) const {
    return gap_mm > skip_ratio * target_spacing_mm;
  }
  [[nodiscard]] bool is_multiple(double gap_mm) const {
    return gap_mm <= multiple_ratio * target_spacing_mm;
  }
};

// What the monitor shows. Counts are whole numbers held in doubles, so every figure is one
// recording column of the signal table.
struct PlantingFigures {
  double seedlings = 0;  // seen by the photo-eye since start
  double spacings = 0;   // spacings counted (within stretches of running)
  double skips = 0;      // spacings over skip_ratio x target
  double multiples = 0;  // spacings at most multiple_ratio x target
  // The spacing figures are 0 while `spacings` is 0: there is nothing to tell yet.
  double singulation_pct = 0;  // 100 - skips - multiples, in % of spacings
  double spacing_mm = 0;       // the last spacing
  double spacing_mean_mm = 0;  // over the run
  double spacing_cv = 0;       // population SD / mean over the run (John Deere: under 0.17)
  double per_m = 0;            // seedlings in the last metre travelled
  // Clamps passed empty since the last seedling, while planting. Counted from the first
  // seedling of a stretch: before it, the disc is still carrying the first seedlings down.
  double empty_clamps_in_row = 0;
  bool empty_belt = false;  // empty_clamps_in_row >= empty_clamps_to_warn: a warning, not a fault
  // Stems whose wall the clamp saw give way since start (firmware/control/stem_reader.h): not
  // the photo-eye's, but counted with the planting so the operator reads them together.
  double damage_seen = 0;
};

class PlantingMonitor {
 public:
  explicit PlantingMonitor(const PlantingMonitorConfig& config);

  // One tick: the seedlings the photo-eye saw (state.seedling_at_m), the distance now, and
  // whether the machine is planting (the chain of spacings breaks while it is not).
  void update(const MachineState& state, bool planting);

  [[nodiscard]] const PlantingFigures& figures() const { return figures_; }
  [[nodiscard]] const PlantingMonitorConfig& config() const { return cfg_; }

 private:
  void on_seedling(double at_m);

  PlantingMonitorConfig cfg_;
  PlantingFigures figures_;
  bool chained_ = false;  // the last seedling was planted in this stretch of running
  double last_at_m_ = 0.0;
  double sum_mm_ = 0.0;
  double sum2_mm2_ = 0.0;
  // The last metre's seedlings: positions in a ring (a metre holds ~34 at the target spacing).
  static constexpr std::size_t kRecent = 256;
  std::array<double, kRecent> recent_m_{};
  std::size_t recent_head_ = 0;
  std::size_t recent_count_ = 0;
};

}  // namespace planter
