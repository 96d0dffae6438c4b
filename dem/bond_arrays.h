#pragma once
// The parallel bonds as a structure of arrays, so that one bond per vector lane is computed
// (dem/bond_kernel.h). Flags are doubles (0 or 1) to keep every lane one width.
#include <cstddef>
#include <vector>

#include "dem/pair_loads.h"
#include "dem/parallel_bond.h"

namespace planter::dem {

struct BondArrays {
  // The pair and its as-built overlap.
  std::vector<int> i, j;
  std::vector<double> rest_overlap_m;
  // The loads carried from step to step (Bond's fields, one array per component).
  std::vector<double> normal_force_N, twist_moment;
  std::vector<double> shear_x, shear_y, shear_z;
  std::vector<double> bending_x, bending_y, bending_z;
  std::vector<double> broken;
  PairLoads loads;  // this step's, on the two particles

  [[nodiscard]] std::size_t size() const { return i.size(); }
  void push_back(const Bond& b);
  [[nodiscard]] Bond bond(std::size_t k) const;
};

}  // namespace planter::dem
