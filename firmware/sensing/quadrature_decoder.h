#pragma once
// x4 quadrature decoding of the soil-wheel encoder's A/B edge events, with a glitch filter.
#include <cstdint>

#include "planter/hal/gpio.h"

namespace planter {

class QuadratureDecoder {
 public:
  // last_count_time_ns() before the first counted edge: no edge has a time yet.
  static constexpr std::int64_t kNoEdgeNs = INT64_MIN;

  explicit QuadratureDecoder(std::int64_t glitch_filter_ns = 0) : glitch_ns_(glitch_filter_ns) {}

  // Line 0 = A, line 1 = B; other lines are ignored.
  void on_edge(const hal::GpioEdge& edge);
  // Sets the levels without counting (at start, from a level read).
  void set_levels(bool a, bool b) {
    a_ = a;
    b_ = b;
  }

  [[nodiscard]] std::int64_t count() const { return count_; }
  [[nodiscard]] std::int64_t last_count_time_ns() const { return last_count_ns_; }
  [[nodiscard]] std::uint32_t invalid_transitions() const { return invalid_; }
  [[nodiscard]] std::uint32_t glitches() const { return glitches_; }
  [[nodiscard]] int direction() const { return direction_; }

 private:
  std::int64_t glitch_ns_;
  bool a_ = false;
  bool b_ = false;
  std::int64_t count_ = 0;
  std::int64_t last_count_ns_ = kNoEdgeNs;
  std::int64_t last_edge_ns_[2] = {INT64_MIN / 2, INT64_MIN / 2};
  std::uint32_t invalid_ = 0;
  std::uint32_t glitches_ = 0;
  int direction_ = 0;
};

}  // namespace planter
