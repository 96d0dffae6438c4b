#pragma once
// `planter-can gnss`: is the GNSS receiver there and good enough? Watches gpsd for a while and
// says of each fix whether the ground fusion would use it (firmware/sensing/ground_fusion.h),
// or checks a receiver's NMEA log sentence by sentence (`--log`). No bus needed.
#include <atomic>
#include <ostream>
#include <string>

#include "config/board_config.h"

namespace planter::cantool {

struct GnssOptions {
  std::string host;  // "" = the board's [gnss] gpsd_host, else 127.0.0.1
  int port = 0;      // 0 = the board's [gnss] gpsd_port, else 2947
  double duration_s = 10.0;
  std::string log_path;  // check this NMEA log instead of watching gpsd
  const std::atomic<bool>* stop = nullptr;
};

// Exit 0 when fixes were used (or the log is clean), 1 otherwise.
int run_gnss(const config::BoardConfig* board, const GnssOptions& options, std::ostream& out,
             std::ostream& err);

}  // namespace planter::cantool
