#pragma once
// Latin hypercube sampling (McKay, Beckman and Conover, Technometrics 21(2), 1979): each of k
// axes cut into n equal strata, one draw in each, the strata shuffled independently per axis.
// planter-sim montecarlo and robustness draw their runs with it.
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <random>
#include <vector>

namespace planter::sim {

// n points in [0, 1)^k: points[i][axis].
inline std::vector<std::vector<double>> latin_hypercube(std::size_t n, std::size_t k,
                                                        std::mt19937_64& rng) {
  std::uniform_real_distribution<double> within(0.0, 1.0);
  std::vector<std::vector<double>> points(n, std::vector<double>(k));
  for (std::size_t axis = 0; axis < k; ++axis) {
    std::vector<std::size_t> stratum(n);
    std::iota(stratum.begin(), stratum.end(), 0);
    std::shuffle(stratum.begin(), stratum.end(), rng);
    for (std::size_t i = 0; i < n; ++i)
      points[i][axis] = (static_cast<double>(stratum[i]) + within(rng)) / static_cast<double>(n);
  }
  return points;
}

}  // namespace planter::sim
