#pragma once
// Ground distance and speed from the soil-wheel count. Speed uses the time between edges
// (not counts per tick), so it stays accurate at a few counts per tick.
#include <array>
#include <cstdint>

namespace planter {

class GroundSpeedEstimator {
 public:
  GroundSpeedEstimator(double metres_per_count, std::int64_t window_ns)
      : m_per_count_(metres_per_count), window_ns_(window_ns) {}

  // Once per tick, with the decoder's count and the time of its last counted edge.
  void update(std::int64_t count, std::int64_t last_edge_ns, std::int64_t now_ns);

  [[nodiscard]] double distance_m() const { return static_cast<double>(count_) * m_per_count_; }
  [[nodiscard]] double speed_mps() const { return speed_mps_; }
  void set_metres_per_count(double m) { m_per_count_ = m; }

 private:
  struct Sample {
    std::int64_t count;
    std::int64_t edge_ns;
  };
  static constexpr std::size_t kHistory = 64;
  double m_per_count_;
  std::int64_t window_ns_;
  std::array<Sample, kHistory> history_{};
  std::size_t head_ = 0;
  std::size_t filled_ = 0;
  std::int64_t count_ = 0;
  double speed_mps_ = 0.0;
};

}  // namespace planter
