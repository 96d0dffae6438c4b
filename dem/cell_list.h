#pragma once
// Neighbour search: particles binned into cubic cells one interaction range wide; candidate
// pairs come out in a fixed order (by i, then j), so a run is deterministic.
#include <utility>
#include <vector>

#include "dem/particle.h"

namespace planter::dem {

class CellList {
 public:
  // Rebuilds the bins; pairs closer than `range_m` (centre to centre) are candidates.
  void build(const std::vector<Particle>& particles, double range_m);
  // Every pair (i < j) whose centres are within range_m, ordered.
  void pairs(const std::vector<Particle>& particles, std::vector<std::pair<int, int>>& out) const;

 private:
  double cell_m_ = 1.0;
  double range_m_ = 0.0;
  Vec3 origin_ = Vec3::Zero();
  int nx_ = 1, ny_ = 1, nz_ = 1;
  std::vector<int> cell_start_;  // CSR layout: particles of cell c are order_[start[c], start[c+1])
  std::vector<int> order_;
  std::vector<int> cell_of_;
};

}  // namespace planter::dem
