#include "firmware/sensing/load_cell_zero.h"

#include <algorithm>

namespace planter {

void LoadCellZero::update(double reading_N, bool open) {
  if (!open) {
    samples_ = 0;
    sum_N_ = 0.0;
    return;
  }
  sum_N_ += reading_N;
  ++samples_;
  offset_N_ = std::clamp(sum_N_ / samples_, -cfg_.max_offset_N, cfg_.max_offset_N);
}

}  // namespace planter
