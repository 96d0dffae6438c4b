#include "firmware/sensing/ground_speed_estimator.h"

#include <algorithm>
#include <cmath>

#include "firmware/sensing/quadrature_decoder.h"

namespace planter {

void GroundSpeedEstimator::update(std::int64_t count, std::int64_t last_edge_ns,
                                  std::int64_t now_ns) {
  count_ = count;
  // Before the first edge there is no time to measure from: a start time taken for an edge
  // made the first speed one count over the whole time since boot (0.25 mm/s against 10 mm/s
  // true in the HIL scenario, issue 32).
  if (last_edge_ns == QuadratureDecoder::kNoEdgeNs) {
    speed_mps_ = 0.0;
    return;
  }
  // Keep one sample per distinct edge time so the window spans real edges.
  const Sample newest{count, last_edge_ns};
  if (filled_ == 0 || history_[(head_ + kHistory - 1) % kHistory].edge_ns != last_edge_ns) {
    history_[head_] = newest;
    head_ = (head_ + 1) % kHistory;
    filled_ = std::min(filled_ + 1, kHistory);
  }
  // Oldest sample still inside the window (at least one step back), never across a standstill:
  // a gap between edges longer than the window, with newer edges after it, is a stop, and the
  // edges before it belong to the speed before the stop (reaching across made the first window
  // after a refill stop read the distance since the stop over its whole time).
  const Sample* oldest = nullptr;
  std::int64_t newer_ns = last_edge_ns;
  for (std::size_t i = 2; i <= filled_; ++i) {
    const Sample& s = history_[(head_ + kHistory - i) % kHistory];
    if (oldest != nullptr && newer_ns - s.edge_ns > window_ns_) break;
    oldest = &s;
    if (last_edge_ns - s.edge_ns >= window_ns_) break;
    newer_ns = s.edge_ns;
  }
  if (oldest == nullptr || last_edge_ns == oldest->edge_ns) {
    speed_mps_ = 0.0;
    return;
  }
  const double dt_s = static_cast<double>(last_edge_ns - oldest->edge_ns) * 1e-9;
  double v = static_cast<double>(count - oldest->count) * m_per_count_ / dt_s;
  // No edge for a while: the speed can be at most one count over the time since the last edge.
  const double since_s = static_cast<double>(now_ns - last_edge_ns) * 1e-9;
  if (since_s > 0.0) {
    const double bound = m_per_count_ / since_s;
    if (std::abs(v) > bound) v = std::copysign(bound, v);
  }
  speed_mps_ = v;
}

}  // namespace planter
