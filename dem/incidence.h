#pragma once
// Which pairs (bonds, or candidate contacts) each particle is in, in pair order, and on which
// side. Summing a particle's pair loads through it gives the bits a pass over the pairs in
// order would (each particle sees the same sequence of additions), and particles can be summed
// on different threads at once.
#include <cstddef>
#include <vector>

namespace planter::dem {

struct Incidence {
  std::vector<int> start;           // particle p's entries are [start[p], start[p + 1])
  std::vector<int> pair;            // the pair's index, ascending within a particle
  std::vector<unsigned char> is_j;  // 1: the particle is the pair's j, 0: its i

  // From the pairs' two particle columns, for `particles` particles.
  void build(std::size_t particles, const std::vector<int>& i, const std::vector<int>& j);
};

}  // namespace planter::dem
