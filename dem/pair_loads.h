#pragma once
// A step's loads of pairs (bonds or contacts) on their two particles, one array per component,
// and how they are added to the particles: in pair order, either in one pass over the pairs or
// by each particle gathering its own (dem/incidence.h), with the same additions in the same
// order either way. Flags are doubles (0 or 1) to keep every vector lane one width.
#include <cstddef>
#include <vector>

#include "dem/incidence.h"
#include "dem/particle.h"

namespace planter::dem {

struct PairLoads {
  // The force on i (j gets its opposite), the torques on i and on j, and whether the pair
  // carried any load this step (1) or not (0: a broken bond, a pair not touching).
  std::vector<double> force_on_i_x, force_on_i_y, force_on_i_z;
  std::vector<double> torque_on_i_x, torque_on_i_y, torque_on_i_z;
  std::vector<double> torque_on_j_x, torque_on_j_y, torque_on_j_z;
  std::vector<double> carried;

  void resize(std::size_t pairs);
  void clear() { resize(0); }
};

// Adds the loads of each pair particle `p` is in to `particle`, in pair order (the order is the
// result's: floating-point sums are not associative). `pairs_of` is the pairs' incidence.
void add_pair_loads(const PairLoads& loads, const Incidence& pairs_of, std::size_t p,
                    Particle& particle);
// The same sums for every particle at once, in one pass over the pairs (`i`, `j` their
// particles): one thread, the arrays read in order.
void add_all_pair_loads(const PairLoads& loads, const std::vector<int>& i,
                        const std::vector<int>& j, std::vector<Particle>& particles);

}  // namespace planter::dem
