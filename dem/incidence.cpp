#include "dem/incidence.h"

#include <utility>

namespace planter::dem {

void Incidence::build(std::size_t particles, const std::vector<int>& i, const std::vector<int>& j) {
  start.assign(particles + 1, 0);
  for (std::size_t k = 0; k < i.size(); ++k) {
    ++start[static_cast<std::size_t>(i[k]) + 1];
    ++start[static_cast<std::size_t>(j[k]) + 1];
  }
  for (std::size_t p = 0; p < particles; ++p) start[p + 1] += start[p];
  pair.assign(2 * i.size(), 0);
  is_j.assign(2 * i.size(), 0);
  std::vector<int> next(start.begin(), start.end() - 1);
  // Pairs in ascending order: each particle's entries come out ascending too.
  for (std::size_t k = 0; k < i.size(); ++k) {
    for (const auto& [p, side] : {std::pair{i[k], 0}, std::pair{j[k], 1}}) {
      const auto at = static_cast<std::size_t>(next[static_cast<std::size_t>(p)]++);
      pair[at] = static_cast<int>(k);
      is_j[at] = static_cast<unsigned char>(side);
    }
  }
}

}  // namespace planter::dem
