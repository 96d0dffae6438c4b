#include "firmware/control/furrow_depth_loop.h"

#include <algorithm>
#include <cmath>

namespace planter {

void FurrowDepthLoop::reset(double measured_depth_mm) {
  ramped_mm_ = measured_depth_mm;
  trim_mm_ = 0.0;
}

double FurrowDepthLoop::update(double measured_mm, double dt_s, bool engaged) {
  const double goal = engaged ? cfg_.target_mm : cfg_.raised_mm;
  const double step = cfg_.rate_mm_per_s * dt_s;
  ramped_mm_ += std::clamp(goal - ramped_mm_, -step, step);
  const bool settled = std::abs(goal - ramped_mm_) < 1e-9;
  if (engaged && settled) {
    trim_mm_ += cfg_.ki_per_s * (ramped_mm_ - measured_mm) * dt_s;
    trim_mm_ = std::clamp(trim_mm_, -cfg_.trim_max_mm, cfg_.trim_max_mm);
  } else if (!engaged) {
    trim_mm_ = 0.0;
  }
  return std::clamp(ramped_mm_ + trim_mm_, cfg_.min_mm, cfg_.max_mm);
}

}  // namespace planter
