#pragma once
// CLOCK_MONOTONIC: the clock that SocketCAN software timestamps, libgpiod edge events and
// clock_nanosleep share, so every time in the controller is on one axis.
#include <time.h>

#include <cstdint>

#include "planter/hal/clock.h"

namespace planter::hal::linux_backend {

inline std::int64_t monotonic_now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

class MonotonicClock final : public Clock {
 public:
  [[nodiscard]] std::int64_t now_ns() const override { return monotonic_now_ns(); }
};

}  // namespace planter::hal::linux_backend
