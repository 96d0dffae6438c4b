#include "apps/planter-can/tool_link.h"

#include <ostream>

#include "apps/planter-can/candump_log.h"

namespace planter::cantool {

void LogWriter::on_frame(std::int64_t time_ns, const hal::CanFrame& frame, bool) {
  out_ << format_log_line(time_ns, interface_, frame) << '\n';
  ++frames_;
}

bool ToolLink::send(const hal::CanFrame& frame) {
  // About 20 ms of retries: enough for a 10-frame queue to drain at 125 kbit/s.
  constexpr int kRetries = 20;
  for (int attempt = 0; attempt <= kRetries; ++attempt) {
    if (try_send(frame)) {
      if (tap_ != nullptr) tap_->on_frame(wall_time_ns(), frame, true);
      return true;
    }
    if (attempt < kRetries) {
      ++paced_;
      back_off();
    }
  }
  ++lost_;
  return false;
}

bool ToolLink::receive(hal::CanFrame& frame) {
  if (!try_receive(frame)) return false;
  if (tap_ != nullptr) tap_->on_frame(rx_time_ns(), frame, false);
  return true;
}

void ToolLink::idle_until(std::int64_t deadline_ns) {
  hal::CanFrame f;
  while (receive_until(f, deadline_ns)) {
  }
}

bool ToolLink::receive_until(hal::CanFrame& frame, std::int64_t deadline_ns) {
  for (;;) {
    if (receive(frame)) return true;
    if (!wait(deadline_ns)) return false;
  }
}

}  // namespace planter::cantool
