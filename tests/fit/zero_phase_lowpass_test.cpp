// The anti-alias filter copies the rows where its sections have settled over a held input
// (analysis/decimation.cpp): what it gives must still be the filter's output at every row.
// The reference here is the same Butterworth design run in direct form I, row by row.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "analysis/decimation.h"

namespace planter::analysis {
namespace {

// One low-pass section by the bilinear transform with pre-warping (Oppenheim & Schafer, 3rd
// ed., sec. 7.3), in direct form I, started from the steady state of its first input.
struct DirectFormOne {
  double b0, b1, b2, a1, a2;
  double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
  DirectFormOne(double cutoff, double rate, double q) {
    const double k = std::tan(std::numbers::pi * cutoff / rate);
    const double norm = 1.0 / (1.0 + k / q + k * k);
    b0 = k * k * norm, b1 = 2.0 * b0, b2 = b0;
    a1 = 2.0 * (k * k - 1.0) * norm, a2 = (1.0 - k / q + k * k) * norm;
  }
  double step(double x) {
    const double y = b0 * x + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
    x2 = x1, x1 = x, y2 = y1, y1 = y;
    return y;
  }
  void settle_at(double x) { x1 = x2 = y1 = y2 = x; }  // a low-pass's gain is 1
};

std::vector<double> reference(std::vector<double> v, double cutoff, double rate) {
  for (int pass = 0; pass < 2; ++pass) {
    DirectFormOne first(cutoff, rate, 1.0 / (2.0 * std::cos(std::numbers::pi / 8.0)));
    DirectFormOne second(cutoff, rate, 1.0 / (2.0 * std::cos(3.0 * std::numbers::pi / 8.0)));
    first.settle_at(v[0]);
    second.settle_at(v[0]);
    for (double& x : v) x = second.step(first.step(x));
    std::reverse(v.begin(), v.end());
  }
  return v;
}

// A clamp's path: held for 1 to 800 rows at a time, between moves and short ramps.
std::vector<double> held_path(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> hold(1, 800), kind(0, 2);
  std::uniform_real_distribution<double> level(-3.0, 12.0);
  std::vector<double> v;
  double at = 0.0;
  while (v.size() < 40000) {
    const int rows = hold(rng);
    if (kind(rng) == 0) {
      const double to = level(rng);
      for (int k = 1; k <= 40; ++k) v.push_back(at + (to - at) * k / 40.0);
      at = to;
    } else {
      at = level(rng);
    }
    v.insert(v.end(), static_cast<std::size_t>(rows), at);
  }
  return v;
}

TEST(ZeroPhaseLowpass, HeldStretchesGiveTheFiltersOutputAtEveryRow) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const std::vector<double> path = held_path(seed);
    for (double cutoff : {0.08, 0.02, 0.3}) {
      std::vector<double> filtered = path;
      zero_phase_lowpass(filtered, cutoff, 1.0);
      const std::vector<double> expected = reference(path, cutoff, 1.0);
      double worst = 0.0, moved = 0.0;
      for (std::size_t k = 0; k < path.size(); ++k) {
        worst = std::max(worst, std::abs(filtered[k] - expected[k]));
        moved = std::max(moved, std::abs(filtered[k] - path[k]));
      }
      EXPECT_LT(worst, 1e-9) << "seed " << seed << ", cut-off " << cutoff;
      EXPECT_GT(moved, 0.1) << "the filter smooths the steps";  // the test exercises it
    }
  }
}

}  // namespace
}  // namespace planter::analysis
