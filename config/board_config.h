#pragma once
// A board, the machine it runs and the unit's calibration: loaded and validated once at
// start; the firmware only sees ControllerConfig.
#include <string>
#include <vector>

#include "config/clamp_ceiling.h"
#include "firmware/controller/controller_config.h"

namespace planter::config {

struct GpioLines {
  std::string chip = "sim";
  int encoder_a = 0;
  int encoder_b = 1;
  int estop = 2;
  int status = 3;
  int seedling_sensor = -1;  // the photo-eye; -1: none fitted
  bool seedling_sensor_active_low = false;
};

// [realtime]: how planterd's control loop is scheduled on the board.
struct RealtimeConfig {
  int priority = 80;     // SCHED_FIFO 1-99; 0 = ordinary scheduling
  int cpu = -1;          // CPU to pin the loop to; -1 = any
  bool require = false;  // refuse to start when SCHED_FIFO or mlockall is refused
};

// [gnss]: the GNSS receiver, where the board has one (its limits go to ControllerConfig::ground).
struct GnssBoardConfig {
  std::string receiver = "none";  // none, sim or gpsd
  std::string gpsd_host = "127.0.0.1";
  int gpsd_port = 2947;
  // The antenna's place from where seedlings leave the disc: ahead along the row, and to the
  // left of it (metres). As-planted positions are the antenna's less this.
  double antenna_ahead_m = 0.0;
  double antenna_left_m = 0.0;
};

// [console]: the operator's web console that planterd serves (console/console_server.h).
struct ConsoleConfig {
  int port = 0;                  // 0: no console
  std::string bind = "0.0.0.0";  // the machine's networks (its Wi-Fi)
  std::string viewer_secret;     // "": viewing is open on the machine's network
};

// A board file (boards/<board>/board.toml) is the board's wiring: its bus, lines, encoder and
// loop timing. It names the machine it runs (machines/<machine>.toml: mechanism, limits,
// control gains, nodes) and this unit's calibration (a file beside it, which `planter-can
// calibrate` writes). A board file naming no machine holds the machine's sections itself.
struct BoardConfig {
  std::string file;
  std::string machine_name;      // "" when the board file holds the machine itself
  std::string machine_file;      // machines/<machine>.toml, as found
  std::string calibration_file;  // "" when the board names none
  std::string name;
  std::string toolchain;
  std::string can_interface = "sim";
  GpioLines gpio;
  RealtimeConfig realtime;
  GnssBoardConfig gnss;
  ConsoleConfig console;
  ControllerConfig controller;
  // The rule the clamp's ceiling (controller.clamp.ceiling_N) is derived by, at the reference stem.
  ClampCeilingRule clamp_ceiling;
  double planned_bus_load_pct = 0;    // config/board_checks.h
  std::vector<std::string> warnings;  // in range but doubtful; tools print them at start
};

// Throws ConfigError on any problem. `calibration` (if not empty) is read instead of the
// calibration file the board names (planter-can checks an edited calibration this way).
BoardConfig load_board(const std::string& path, const std::string& calibration = "");
// The files a loaded board was built from: the board, its machine and its calibration.
std::vector<std::string> source_files(const BoardConfig& board);

}  // namespace planter::config
