#pragma once
// CLOCK_MONOTONIC: the clock that SocketCAN software timestamps, libgpiod edge events and
// clock_nanosleep share, so every time in the controller is on one axis.
#include <time.h>

#include <cstdint>

namespace planter::hal::linux_backend {

inline std::int64_t timespec_ns(const timespec& ts) {
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

inline std::int64_t monotonic_now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return timespec_ns(ts);
}

// Wall-clock time, only to place logs beside candump's timestamps; never for control.
inline std::int64_t realtime_now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return timespec_ns(ts);
}

}  // namespace planter::hal::linux_backend
