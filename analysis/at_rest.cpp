#include "analysis/at_rest.h"

#include <algorithm>
#include <cmath>

#include "analysis/decimation.h"

namespace planter::analysis {

std::vector<bool> wheel_at_rest(const Recording& r) {
  const std::vector<double>& wheel = r.at("v_wheel");
  const std::size_t n = wheel.size();
  const double rate = sample_rate_hz(r);
  const auto half = static_cast<std::size_t>(std::ceil(kRestHalfWindow_s * std::max(rate, 0.0)));
  std::vector<std::size_t> moving_before(n + 1, 0);  // prefix count of moving samples
  for (std::size_t k = 0; k < n; ++k) moving_before[k + 1] = moving_before[k] + (wheel[k] != 0.0);
  std::vector<bool> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t lo = k > half ? k - half : 0, hi = std::min(n, k + half + 1);
    out[k] = moving_before[hi] == moving_before[lo];
  }
  return out;
}

}  // namespace planter::analysis
