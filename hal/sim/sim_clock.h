#pragma once
#include <cstdint>

namespace planter::hal::sim {

// Simulated time, owned and advanced by the lockstep runner alone. The firmware never reads a
// clock: each tick is handed its time.
class SimClock {
 public:
  [[nodiscard]] std::int64_t now_ns() const { return now_ns_; }
  void advance_ns(std::int64_t dt_ns) { now_ns_ += dt_ns; }
  void set_ns(std::int64_t t_ns) { now_ns_ = t_ns; }

 private:
  std::int64_t now_ns_ = 0;
};

}  // namespace planter::hal::sim
