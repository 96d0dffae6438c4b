#pragma once
#include <cstdint>

namespace planter::hal {

// The controller's edge lines, by their index in its GpioEdgeSource.
namespace edge_line {
constexpr std::uint8_t kEncoderA = 0;        // soil-wheel encoder, channel A
constexpr std::uint8_t kEncoderB = 1;        // soil-wheel encoder, channel B
constexpr std::uint8_t kSeedlingSensor = 2;  // the photo-eye where seedlings leave the disc
}  // namespace edge_line

struct GpioEdge {
  std::uint8_t line = 0;     // index into the source's lines (edge_line::)
  bool rising = false;       // the line became asserted (after the board's active-low setting)
  std::int64_t time_ns = 0;  // when the edge happened (kernel or simulated timestamp)
};

// A set of input lines that report edge events, merged in time order: the soil-wheel encoder's
// A/B lines and, where fitted, the seedling photo-eye.
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
