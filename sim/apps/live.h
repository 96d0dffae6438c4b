#pragma once
// planter-sim live: the simulated machine in real time with the operator's console, so the
// console can be tried with no hardware.
#include <string>

#include "console/console_server.h"

namespace planter::sim {

struct LiveOptions {
  console::ConsoleOptions console;
  double duration_s = 0.0;  // simulated seconds; 0: until Ctrl-C
  double speed = 1.0;       // simulated seconds per wall second
};

int run_live(const std::string& scenario_path, const LiveOptions& options);

}  // namespace planter::sim
