#include "firmware/control/furrow_depth_loop.h"

#include <algorithm>
#include <cmath>

namespace planter {

void FurrowDepthLoop::reset(double measured_depth_mm) {
  ramped_mm_ = measured_depth_mm;
  trim_mm_ = 0.0;
  status_ = DepthStatus{};
}

double FurrowDepthLoop::update(double measured_mm, double dt_s, bool engaged) {
  const double goal = engaged ? cfg_.target_mm : cfg_.raised_mm;
  const double step = cfg_.rate_mm_per_s * dt_s;
  ramped_mm_ += std::clamp(goal - ramped_mm_, -step, step);
  const bool settled = std::abs(goal - ramped_mm_) < 1e-9;
  if (engaged && settled) {
    trim_mm_ += cfg_.ki_per_s * (ramped_mm_ - measured_mm) * dt_s;
    // The travel bounds the trim: what the end stops allow, nothing past them.
    trim_mm_ = std::clamp(trim_mm_, cfg_.min_mm - ramped_mm_, cfg_.max_mm - ramped_mm_);
  } else if (!engaged) {
    trim_mm_ = 0.0;
  }
  const double command = std::clamp(ramped_mm_ + trim_mm_, cfg_.min_mm, cfg_.max_mm);
  status_.settled = engaged && settled;
  status_.error_mm = ramped_mm_ - measured_mm;
  status_.at_end_stop = command >= cfg_.max_mm - 1e-9 || command <= cfg_.min_mm + 1e-9;
  return command;
}

}  // namespace planter
