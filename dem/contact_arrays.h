#pragma once
// The candidate pairs of the Verlet list as a structure of arrays (one pair per vector lane in
// dem/contact_kernel.h): the pair, its Hertz-Mindlin constants, its contact history, and this
// step's loads. Flags are doubles (0 or 1) to keep every lane one width.
#include <cstddef>
#include <vector>

#include "dem/hertz_mindlin.h"
#include "dem/pair_loads.h"
#include "dem/pair_property_columns.h"

namespace planter::dem {

struct ContactArrays {
  std::vector<int> i, j;
  std::vector<int> bond;               // index into the bonds for a pair bonded at build, or -1
  std::vector<double> rest_overlap_m;  // the bonded pair's as-built overlap, else 0
  PairPropertyColumns constants;       // the pairs' PairProperties
  std::vector<double> spring_x, spring_y, spring_z;  // tangential spring (history)
  PairLoads loads;  // this step's, on the two particles (carried: the pair touched)

  [[nodiscard]] std::size_t size() const { return i.size(); }
  void clear();
  void push_back(int pi, int pj, int bond_index, double rest_overlap, const PairProperties& p,
                 const Vec3& spring);
  [[nodiscard]] PairProperties properties(std::size_t k) const;
  [[nodiscard]] Vec3 spring(std::size_t k) const;
};

}  // namespace planter::dem
