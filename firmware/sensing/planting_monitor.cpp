#include "firmware/sensing/planting_monitor.h"

#include <algorithm>
#include <cmath>

namespace planter {

PlantingMonitor::PlantingMonitor(const PlantingMonitorConfig& config) : cfg_(config) {}

void PlantingMonitor::update(const MachineState& state, bool planting) {
  const std::uint32_t seen =
      std::min<std::uint32_t>(state.seedlings_this_tick, MachineState::kMaxSeedlingsPerTick);
  for (std::uint32_t i = 0; i < seen; ++i) on_seedling(state.seedling_at_m[i]);

  // The open gap since the last seedling, in clamps that passed empty.
  const double target_m = cfg_.target_spacing_mm * 1e-3;
  double empty = 0.0;
  if (planting && chained_ && target_m > 0.0) {
    empty = std::max(0.0, std::floor((state.distance_m - last_at_m_) / target_m + 0.5) - 1.0);
  }
  if (!planting) chained_ = false;
  figures_.empty_clamps_in_row = empty;
  figures_.empty_belt =
      cfg_.empty_clamps_to_warn > 0 && empty >= static_cast<double>(cfg_.empty_clamps_to_warn);

  // Seedlings within the last metre travelled.
  std::size_t in_metre = 0;
  for (std::size_t k = 0; k < recent_count_; ++k) {
    const double at = recent_m_[(recent_head_ + kRecent - 1 - k) % kRecent];
    if (state.distance_m - at > 1.0) break;
    ++in_metre;
  }
  figures_.per_m = static_cast<double>(in_metre);
}

void PlantingMonitor::on_seedling(double at_m) {
  figures_.seedlings += 1.0;
  recent_m_[recent_head_] = at_m;
  recent_head_ = (recent_head_ + 1) % kRecent;
  recent_count_ = std::min(recent_count_ + 1, kRecent);
  if (chained_) {
    const double gap_mm = (at_m - last_at_m_) * 1e3;
    figures_.spacings += 1.0;
    if (cfg_.is_skip(gap_mm)) figures_.skips += 1.0;
    if (cfg_.is_multiple(gap_mm)) figures_.multiples += 1.0;
    sum_mm_ += gap_mm;
    sum2_mm2_ += gap_mm * gap_mm;
    const double n = figures_.spacings;
    figures_.spacing_mm = gap_mm;
    figures_.spacing_mean_mm = sum_mm_ / n;
    const double variance =
        std::max(0.0, sum2_mm2_ / n - figures_.spacing_mean_mm * figures_.spacing_mean_mm);
    figures_.spacing_cv =
        figures_.spacing_mean_mm > 0.0 ? std::sqrt(variance) / figures_.spacing_mean_mm : 0.0;
    figures_.singulation_pct = 100.0 * (1.0 - (figures_.skips + figures_.multiples) / n);
  }
  chained_ = true;
  last_at_m_ = at_m;
}

}  // namespace planter
