#pragma once
// candump -L log lines: "(1700000000.123456) can0 123#DEADBEEF". Written exactly as can-utils
// writes them (10-digit seconds, 6-digit microseconds, 3 hex digits for standard IDs, 8 for
// extended and error frames, "#R" for remote), so canplayer and python-can read them back.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "planter/hal/can_frame.h"

namespace planter::cantool {

struct LogRecord {
  std::int64_t time_ns = 0;
  std::string interface;
  hal::CanFrame frame;
};

std::string format_log_line(std::int64_t time_ns, std::string_view interface,
                            const hal::CanFrame& frame);

enum class LogLineKind : std::uint8_t { kFrame, kSkip, kError };
struct LogParse {
  LogLineKind kind = LogLineKind::kSkip;
  LogRecord record;
  std::string error;  // what is wrong, for kError
};
// Lines not starting with '(' are skipped (canplayer does the same). CAN FD frames ("##")
// are reported as errors: this machine's bus is classic CAN.
LogParse parse_log_line(std::string_view line);

}  // namespace planter::cantool
