#include "analysis/glitches.h"

#include <algorithm>
#include <cmath>

namespace planter::analysis {
namespace {

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// The smallest jump a spike must make on both sides, for this column.
double spike_threshold(const std::vector<double>& y) {
  std::vector<double> steps;
  steps.reserve(y.size());
  for (std::size_t k = 1; k < y.size(); ++k) steps.push_back(std::abs(y[k] - y[k - 1]));
  const double range = quantile(y, 0.99) - quantile(y, 0.01);
  return std::max(20.0 * quantile(std::move(steps), 0.90), 0.2 * range);
}

}  // namespace

std::vector<Glitch> find_glitches(const Recording& r, const std::vector<std::string>& columns) {
  std::vector<Glitch> found;
  for (const std::string& name : columns) {
    if (!r.has(name)) continue;
    const std::vector<double>& y = r.at(name);
    if (y.size() < 3) continue;
    const double limit = spike_threshold(y);
    if (!(limit > 0.0)) continue;  // a constant column has no spike
    for (std::size_t k = 1; k + 1 < y.size(); ++k) {
      const double before = y[k] - y[k - 1], after = y[k] - y[k + 1];
      const bool spike = std::abs(before) > limit && std::abs(after) > limit &&
                         (before > 0) == (after > 0) && std::abs(y[k + 1] - y[k - 1]) < 0.5 * limit;
      if (spike) found.push_back({name, r.t[k], y[k], 0.5 * (y[k - 1] + y[k + 1])});
    }
  }
  return found;
}

Recording without_glitches(const Recording& r, const std::vector<Glitch>& glitches) {
  Recording out = r;
  for (const Glitch& g : glitches) {
    const auto it = std::lower_bound(out.t.begin(), out.t.end(), g.t_s);
    if (it == out.t.end() || *it != g.t_s) continue;
    out.signals[g.column][static_cast<std::size_t>(it - out.t.begin())] = g.replaced_by;
  }
  return out;
}

}  // namespace planter::analysis
