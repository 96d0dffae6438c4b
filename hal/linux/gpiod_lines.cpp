#include "hal/linux/gpiod_lines.h"

#include <errno.h>
#include <fcntl.h>
#include <gpiod.h>

#include <algorithm>
#include <cstring>

#include "hal/linux/hal_error.h"
#include "hal/linux/monotonic_clock.h"

namespace planter::hal::linux_backend {
namespace {

constexpr const char* kConsumer = "planterd";

std::string errno_text() { return std::strerror(errno); }

}  // namespace

GpiodChip::GpiodChip(const std::string& name) : name_(name), chip_(nullptr) {
  chip_ = gpiod_chip_open_lookup(name.c_str());
  if (chip_ == nullptr)
    throw HalError("'gpio.chip': chip '" + name +
                   "' not found (`gpiodetect` lists the chips by name and label)");
}

GpiodChip::~GpiodChip() { gpiod_chip_close(chip_); }

std::string GpiodChip::kernel_name() const { return gpiod_chip_name(chip_); }

gpiod_line* GpiodChip::line(int offset, const std::string& what) {
  const unsigned count = gpiod_chip_num_lines(chip_);
  if (offset < 0 || static_cast<unsigned>(offset) >= count)
    throw HalError("'" + what + "' = " + std::to_string(offset) + ": chip '" + name_ +
                   "' has no such line (it has lines 0-" +
                   std::to_string(count == 0 ? 0 : count - 1) + ")");
  gpiod_line* l = gpiod_chip_get_line(chip_, static_cast<unsigned>(offset));
  if (l == nullptr)
    throw HalError("gpio: " + what + " line " + std::to_string(offset) + " on '" + name_ +
                   "': " + errno_text());
  return l;
}

GpiodEdgeSource::GpiodEdgeSource(GpiodChip& chip, int line_a, int line_b, int seedling_line,
                                 bool seedling_active_low) {
  const int offsets[3] = {line_a, line_b, seedling_line};
  const char* names[3] = {"gpio.encoder_a_line", "gpio.encoder_b_line",
                          "gpio.seedling_sensor_line"};
  line_count_ = seedling_line >= 0 ? 3 : 2;
  for (std::size_t i = 0; i < line_count_; ++i) {
    lines_[i] = chip.line(offsets[i], names[i]);
    const int flags = i == 2 && seedling_active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0;
    if (gpiod_line_request_both_edges_events_flags(lines_[i], kConsumer, flags) != 0)
      throw HalError("gpio: cannot request edge events on " + std::string(names[i]) + " line " +
                     std::to_string(offsets[i]) + " of '" + chip.name() + "': " + errno_text());
    fds_[i] = gpiod_line_event_get_fd(lines_[i]);
    const int fl = fcntl(fds_[i], F_GETFL);
    fcntl(fds_[i], F_SETFL, fl | O_NONBLOCK);
  }
}

GpiodEdgeSource::~GpiodEdgeSource() {
  for (gpiod_line* l : lines_)
    if (l != nullptr) gpiod_line_release(l);
}

bool GpiodEdgeSource::level(int index) const {
  return gpiod_line_get_value(lines_[static_cast<std::size_t>(index)]) == 1;
}

void GpiodEdgeSource::refill() {
  // Events held back last time stay, in front.
  std::copy(pending_.begin() + static_cast<std::ptrdiff_t>(pending_next_),
            pending_.begin() + static_cast<std::ptrdiff_t>(pending_count_), pending_.begin());
  pending_count_ -= pending_next_;
  pending_next_ = 0;
  // The lines come from queues read one after the other: an A edge can arrive after A was
  // read but before a later B edge is read. Only edges stamped before the reads began are
  // handed out now; later ones wait for the next refill, so the order is always right.
  const std::int64_t cut_ns = monotonic_now_ns();
  for (std::size_t i = 0; i < line_count_; ++i) {
    gpiod_line_event events[16];
    const std::size_t room = std::min<std::size_t>(16, pending_.size() - pending_count_);
    if (room == 0) break;
    const int n = gpiod_line_event_read_fd_multiple(fds_[i], events, static_cast<unsigned>(room));
    for (int k = 0; k < n; ++k) {
      GpioEdge& e = pending_[pending_count_++];
      e.line = static_cast<std::uint8_t>(i);
      e.rising = events[k].event_type == GPIOD_LINE_EVENT_RISING_EDGE;
      e.time_ns = timespec_ns(events[k].ts);
    }
  }
  // The decoder, and the photo-eye's distance, need the edges in the order they happened.
  std::stable_sort(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(pending_count_),
                   [](const GpioEdge& x, const GpioEdge& y) { return x.time_ns < y.time_ns; });
  ready_count_ = 0;
  while (ready_count_ < pending_count_ && pending_[ready_count_].time_ns <= cut_ns) ++ready_count_;
  // A full buffer must drain even if its stamps are odd (a clock other than monotonic).
  if (ready_count_ == 0 && pending_count_ == pending_.size()) ready_count_ = pending_count_;
}

bool GpiodEdgeSource::next_edge(GpioEdge& edge) {
  if (pending_next_ >= ready_count_) refill();
  if (pending_next_ >= ready_count_) return false;
  edge = pending_[pending_next_++];
  return true;
}

GpiodInput::GpiodInput(GpiodChip& chip, int offset, bool active_low, const std::string& what)
    : line_(chip.line(offset, what)) {
  const int flags = active_low ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0;
  if (gpiod_line_request_input_flags(line_, kConsumer, flags) != 0)
    throw HalError("gpio: cannot request " + what + " line " + std::to_string(offset) + " of '" +
                   chip.name() + "' as input: " + errno_text());
}

GpiodInput::~GpiodInput() { gpiod_line_release(line_); }

bool GpiodInput::asserted() const {
  // A read error counts as asserted: an e-stop that cannot be read must stop the machine.
  return gpiod_line_get_value(line_) != 0;
}

GpiodOutput::GpiodOutput(GpiodChip& chip, int offset, const std::string& what)
    : line_(chip.line(offset, what)) {
  if (gpiod_line_request_output(line_, kConsumer, 0) != 0)
    throw HalError("gpio: cannot request " + what + " line " + std::to_string(offset) + " of '" +
                   chip.name() + "' as output: " + errno_text());
}

GpiodOutput::~GpiodOutput() { gpiod_line_release(line_); }

void GpiodOutput::set(bool on) {
  if (on == last_) return;
  last_ = on;
  gpiod_line_set_value(line_, on ? 1 : 0);
}

}  // namespace planter::hal::linux_backend
