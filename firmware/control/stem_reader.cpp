#include "firmware/control/stem_reader.h"

#include <algorithm>

namespace planter {

void StemReader::reset() {
  has_last_ = false;
  stem_mm_ = 0.0;
  rate_mm_per_s_ = 0.0;
}

double StemReader::stem_in_mm(double rim_speed_mm_per_s) const {
  if (!(rate_mm_per_s_ > cfg_.entry_rate_min_mm_per_s)) return stem_mm_;
  const double horizon_s =
      std::min(cfg_.entry_horizon_max_s, cfg_.entry_mm / std::max(1e-9, rim_speed_mm_per_s));
  return stem_mm_ + rate_mm_per_s_ * horizon_s;
}

void StemReader::update(double added_mm, double dt_s) {
  if (!has_baseline_) {
    baseline_mm_ = added_mm;
    has_baseline_ = true;
  }
  if (has_last_ && added_mm - last_added_mm_ < -cfg_.collapse_mm) ++collapses_;
  read_s_ += dt_s;
  // First-order lags (exact discretisation is not needed at dt << tau).
  baseline_mm_ += (added_mm - baseline_mm_) * std::min(1.0, dt_s / cfg_.baseline_tau_s);
  const double stem_now = added_mm - baseline_mm_;
  const double before_mm = stem_mm_;
  stem_mm_ += (stem_now - stem_mm_) * std::min(1.0, dt_s / cfg_.filter_tau_s);
  if (has_last_ && dt_s > 0.0) {
    const double rate_now = (stem_mm_ - before_mm) / dt_s;
    rate_mm_per_s_ += (rate_now - rate_mm_per_s_) * std::min(1.0, dt_s / cfg_.filter_tau_s);
  }
  last_added_mm_ = added_mm;
  has_last_ = true;
}

}  // namespace planter
