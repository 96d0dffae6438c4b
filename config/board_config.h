#pragma once
// A board file (boards/<board>/board.toml): the machine's buses, lines, nodes and loop
// settings. Loaded and validated once at start; the firmware only sees ControllerConfig.
#include <string>
#include <vector>

#include "firmware/controller/controller_config.h"

namespace planter::config {

// The lowest peak radial compressive force measured on a seedling (the paper's six tests:
// 127.2-191.6 N). A clamp ceiling must stay below it.
constexpr double kSeedlingDamageThresholdN = 127.2;

struct GpioLines {
  std::string chip = "sim";
  int encoder_a = 0;
  int encoder_b = 1;
  int estop = 2;
  int status = 3;
};

// [realtime]: how planterd's control loop is scheduled on the board.
struct RealtimeConfig {
  int priority = 80;     // SCHED_FIFO 1-99; 0 = ordinary scheduling
  int cpu = -1;          // CPU to pin the loop to; -1 = any
  bool require = false;  // refuse to start when SCHED_FIFO or mlockall is refused
};

struct BoardConfig {
  std::string file;
  std::string name;
  std::string toolchain;
  std::string can_interface = "sim";
  GpioLines gpio;
  RealtimeConfig realtime;
  ControllerConfig controller;
  double planned_bus_load_pct = 0;    // config/board_checks.h
  std::vector<std::string> warnings;  // in range but doubtful; tools print them at start
};

// Throws ConfigError on any problem.
BoardConfig load_board(const std::string& path);

}  // namespace planter::config
