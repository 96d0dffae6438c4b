#pragma once
// Measures encoder-edge-to-CAN-command latency: wraps the encoder's edge source, remembers
// the kernel timestamps of the edges the controller took in this tick, and after the tick
// (whose commands are then written to the CAN socket) adds now - edge time to a histogram.
#include <array>
#include <cstddef>
#include <cstdint>

#include "hal/linux/rt_loop.h"
#include "planter/hal/gpio.h"

namespace planter::daemon {

class EdgeLatencyProbe final : public hal::GpioEdgeSource {
 public:
  explicit EdgeLatencyProbe(hal::GpioEdgeSource& inner) : inner_(inner) {}
  bool next_edge(hal::GpioEdge& edge) override {
    if (!inner_.next_edge(edge)) return false;
    if (taken_ < times_.size()) times_[taken_++] = edge.time_ns;
    return true;
  }
  [[nodiscard]] std::uint32_t overflow_count() const override { return inner_.overflow_count(); }
  // Call once the tick's commands are on the bus.
  void tick_done(std::int64_t now_ns) {
    for (std::size_t i = 0; i < taken_; ++i) histogram_.add(now_ns - times_[i]);
    taken_ = 0;
  }
  [[nodiscard]] const hal::linux_backend::LatencyHistogram& histogram() const { return histogram_; }

 private:
  hal::GpioEdgeSource& inner_;
  std::array<std::int64_t, 256> times_{};
  std::size_t taken_ = 0;
  hal::linux_backend::LatencyHistogram histogram_;
};

}  // namespace planter::daemon
