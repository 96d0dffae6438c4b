#include "config/recording_format.h"

#include <cstdio>

#include "firmware/io/signal_table.h"

namespace planter::config {

std::string controller_columns() {
  std::string head;
  for (const SignalDecl& s : kSignals) {
    if (!s.recorded) continue;
    if (!head.empty()) head += ',';
    head += s.column;
  }
  return head;
}

int format_controller_columns(char* out, std::size_t size, double t_s, const Telemetry& c) {
  std::size_t used = 0;
  int total = 0;
  for (const SignalDecl& s : kSignals) {
    if (!s.recorded) continue;
    char* at = used < size ? out + used : nullptr;
    const std::size_t room = used < size ? size - used : 0;
    const char* sep = total == 0 ? "" : ",";
    int n = 0;
    if (s.source == SignalSource::kClock) {
      n = std::snprintf(at, room, "%s%.*f", sep, s.decimals, t_s);
    } else if (s.source == SignalSource::kSupervisor) {
      n = std::snprintf(at, room, "%s%s", sep, supervisor_state_name(c.state));
    } else if (s.source == SignalSource::kWarnings) {
      n = std::snprintf(at, room, "%s%u", sep, static_cast<unsigned>(c.warnings));
    } else if (s.monitored != nullptr) {
      n = std::snprintf(at, room, "%s%.*f", sep, s.decimals, c.planting.*s.monitored);
    } else if (s.measured != nullptr) {
      n = std::snprintf(at, room, "%s%.*f", sep, s.decimals, c.*s.measured);
    } else if (s.commanded != nullptr) {
      n = std::snprintf(at, room, "%s%.*f", sep, s.decimals, c.*s.commanded);
    } else {  // the encoder's count
      n = std::snprintf(at, room, "%s%lld", sep, static_cast<long long>(c.wheel_counts));
    }
    if (n < 0) return n;
    total += n;
    used += static_cast<std::size_t>(n);
  }
  return total;
}

}  // namespace planter::config
