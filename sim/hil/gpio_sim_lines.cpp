#include "sim/hil/gpio_sim_lines.h"

#include <fcntl.h>
#include <unistd.h>

#include "hal/linux/gpiod_lines.h"
#include "hal/linux/hal_error.h"

namespace planter::sim {

using hal::linux_backend::HalError;

GpioSimLines::GpioSimLines(const std::string& chip, const std::vector<int>& offsets) {
  if (offsets.size() > kMaxLines) throw HalError("gpio-sim: more lines than a board has");
  hal::linux_backend::GpiodChip gpio(chip);
  const std::string dir = "/sys/bus/gpio/devices/" + gpio.kernel_name();
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    gpio.line(offsets[i], "line");  // throws when the chip has no such line
    const std::string pull = dir + "/sim_gpio" + std::to_string(offsets[i]) + "/pull";
    fds_[i] = open(pull.c_str(), O_WRONLY | O_CLOEXEC);
    if (fds_[i] < 0)
      throw HalError("'--gpio': chip '" + chip + "' is not a gpio-sim chip (no " + pull + ")");
    const std::string value = dir + "/sim_gpio" + std::to_string(offsets[i]) + "/value";
    value_fds_[i] = open(value.c_str(), O_RDONLY | O_CLOEXEC);
  }
}

GpioSimLines::~GpioSimLines() {
  for (int fd : fds_)
    if (fd >= 0) close(fd);
  for (int fd : value_fds_)
    if (fd >= 0) close(fd);
}

bool GpioSimLines::output_level(int index) const {
  const int fd = value_fds_[static_cast<std::size_t>(index)];
  char c = 0;
  return fd >= 0 && pread(fd, &c, 1, 0) == 1 && c == '1';
}

void GpioSimLines::set(int index, bool high) {
  const auto i = static_cast<std::size_t>(index);
  if (level_[i] == static_cast<int>(high)) return;
  level_[i] = high;
  const char* text = high ? "pull-up" : "pull-down";
  const std::size_t len = high ? 7 : 9;
  if (pwrite(fds_[i], text, len, 0) == static_cast<ssize_t>(len)) ++writes_;
}

}  // namespace planter::sim
