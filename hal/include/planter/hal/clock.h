#pragma once
#include <cstdint>

namespace planter::hal {

// Monotonic time in nanoseconds. The firmware never reads any other clock.
class Clock {
 public:
  virtual ~Clock() = default;
  [[nodiscard]] virtual std::int64_t now_ns() const = 0;
};

}  // namespace planter::hal
