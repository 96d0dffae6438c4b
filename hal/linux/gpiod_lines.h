#pragma once
// GPIO through libgpiod 1.6 (Debian 12): the soil-wheel encoder's A/B lines as edge events,
// the e-stop input and the status output. Chips and lines are checked when opened, so a
// board file naming a chip or line that does not exist fails at start with one message.
#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "planter/hal/gpio.h"

struct gpiod_chip;
struct gpiod_line;

namespace planter::hal::linux_backend {

// An open chip; `name` may be a name (gpiochip0), a path (/dev/gpiochip0), a label or a number.
class GpiodChip {
 public:
  explicit GpiodChip(const std::string& name);  // throws HalError
  ~GpiodChip();
  GpiodChip(const GpiodChip&) = delete;
  GpiodChip& operator=(const GpiodChip&) = delete;
  // Throws HalError naming `what` when the chip has no such line.
  gpiod_line* line(int offset, const std::string& what);
  [[nodiscard]] const std::string& name() const { return name_; }
  // The kernel's name of the chip (gpiochipN), whatever name it was opened by.
  [[nodiscard]] std::string kernel_name() const;

 private:
  std::string name_;
  gpiod_chip* chip_;
};

// Both edges of the encoder's two lines and, where fitted, the seedling photo-eye's (indices
// as edge_line::), merged in kernel-timestamp order (CLOCK_MONOTONIC).
class GpiodEdgeSource final : public GpioEdgeSource {
 public:
  // `seedling_line` -1: no photo-eye. An active-low photo-eye's beam break reads as rising.
  GpiodEdgeSource(GpiodChip& chip, int line_a, int line_b, int seedling_line = -1,
                  bool seedling_active_low = false);
  ~GpiodEdgeSource() override;
  bool next_edge(GpioEdge& edge) override;
  // The v1 uAPI of libgpiod 1.6 drops events silently when its per-line FIFO is full; the
  // decoder's invalid-transition count is what shows such a loss. Always 0 here.
  [[nodiscard]] std::uint32_t overflow_count() const override { return 0; }
  // Current levels, to seed the decoder before the first edge.
  [[nodiscard]] bool level(int index) const;
  [[nodiscard]] int fd(int index) const { return fds_[static_cast<std::size_t>(index)]; }

 private:
  void refill();

  std::array<gpiod_line*, 3> lines_{};
  std::array<int, 3> fds_{-1, -1, -1};
  std::size_t line_count_ = 2;
  std::array<GpioEdge, 64> pending_{};
  std::size_t pending_count_ = 0;
  std::size_t pending_next_ = 0;
  std::size_t ready_count_ = 0;  // pending_[0, ready_count_) are safe to hand out in order
};

class GpiodInput final : public DigitalInput {
 public:
  GpiodInput(GpiodChip& chip, int offset, bool active_low, const std::string& what);
  ~GpiodInput() override;
  [[nodiscard]] bool asserted() const override;

 private:
  gpiod_line* line_;
};

class GpiodOutput final : public DigitalOutput {
 public:
  GpiodOutput(GpiodChip& chip, int offset, const std::string& what);
  ~GpiodOutput() override;
  void set(bool on) override;

 private:
  gpiod_line* line_;
  bool last_ = false;
};

}  // namespace planter::hal::linux_backend
