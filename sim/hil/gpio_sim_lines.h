#pragma once
// Drives input lines of a gpio-sim chip (the kernel's GPIO simulator) from user space by
// writing each line's pull: "pull-up" makes the controller's libgpiod see a rising edge,
// "pull-down" a falling one. This is how the simulated soil wheel reaches a real GPIO chip.
#include <array>
#include <string>
#include <vector>

namespace planter::sim {

class GpioSimLines {
 public:
  // `chip` as libgpiod names it (gpiochipN, path or label). Throws HalError when the chip
  // does not exist, is not a gpio-sim chip, or lacks a line.
  // At most kMaxLines offsets: encoder A, B, e-stop, status and the seedling photo-eye.
  static constexpr std::size_t kMaxLines = 5;
  GpioSimLines(const std::string& chip, const std::vector<int>& offsets);
  ~GpioSimLines();
  GpioSimLines(const GpioSimLines&) = delete;
  GpioSimLines& operator=(const GpioSimLines&) = delete;
  // index into the offsets given at construction.
  void set(int index, bool high);
  // The level the controller drives on an output line (gpio-sim's `value`); false when unreadable.
  [[nodiscard]] bool output_level(int index) const;
  [[nodiscard]] unsigned writes() const { return writes_; }

 private:
  std::array<int, kMaxLines> fds_{-1, -1, -1, -1, -1};
  std::array<int, kMaxLines> value_fds_{-1, -1, -1, -1, -1};
  std::array<int, kMaxLines> level_{-1, -1, -1, -1, -1};
  unsigned writes_ = 0;
};

}  // namespace planter::sim
