#pragma once
// planter-sim live: the simulated machine in real time with the operator's console, so the
// console can be tried with no hardware.
#include <string>

#include "console/console_server.h"

namespace planter::sim {

struct LiveOptions {
  console::ConsoleOptions console;
  double duration_s = 0.0;          // simulated seconds; 0: until Ctrl-C
  double speed = 1.0;               // simulated seconds per wall second
  std::string dir = "out/live";     // recordings/ and audit.log
  std::string pairing_secret_file;  // empty: a new secret, shown on the terminal
  std::string viewer_secret_file;   // empty: viewing is open
  bool view_only = false;           // no commands at all
};

int run_live(const std::string& scenario_path, const LiveOptions& options);

}  // namespace planter::sim
