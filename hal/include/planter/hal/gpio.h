#pragma once
#include <cstdint>

namespace planter::hal {

struct GpioEdge {
  std::uint8_t line = 0;  // index into the source's lines, e.g. 0 = encoder A, 1 = encoder B
  bool rising = false;
  std::int64_t time_ns = 0;  // when the edge happened (kernel or simulated timestamp)
};

// A set of input lines that report edge events (the soil-wheel encoder A/B lines).
class GpioEdgeSource {
 public:
  virtual ~GpioEdgeSource() = default;
  // Takes the oldest pending edge. False when none is pending.
  virtual bool next_edge(GpioEdge& edge) = 0;
  // Edges lost because the event queue overflowed.
  [[nodiscard]] virtual std::uint32_t overflow_count() const = 0;
};

class DigitalInput {
 public:
  virtual ~DigitalInput() = default;
  // Physical line level after the board's active-low setting: true = asserted.
  [[nodiscard]] virtual bool asserted() const = 0;
};

class DigitalOutput {
 public:
  virtual ~DigitalOutput() = default;
  virtual void set(bool on) = 0;
};

}  // namespace planter::hal
