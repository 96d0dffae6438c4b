#pragma once
// A scenario file (scenarios/*.toml): which board, the field, the seedlings, the effects
// switched on, and the faults injected. Validated on load.
#include <cstdint>
#include <string>

#include "config/board_config.h"
#include "sim/plant/plant_config.h"

namespace planter::sim {

struct Scenario {
  std::string file;
  std::string name;
  std::uint64_t seed = 1;
  double tail_s = 3.0;  // keep running this long after the machine reached the end
  double max_duration_s = 3600.0;
  config::BoardConfig board;
  PlantConfig plant;
  FaultEvents faults;
  // A bound, not a machine (the grip benchmark's third arm, issue 50): the clamp is told each
  // stem's true first peak as it comes in and aims 5 % below it (at most the set-point), which
  // no sensor on the machine can tell it. How much damage knowing the strength would save.
  bool clamp_told_each_stem = false;
  // The script's operator presses run once the controller is ready (and again after a link
  // reset or a planting-off stop). Off where a person is at the console (`planter-sim live`):
  // the machine then waits for Start, as one just powered does.
  bool operator_presses_run = true;
};

// Throws config::ConfigError.
Scenario load_scenario(const std::string& path);
// A seedling force model file written by `planter-dem reduce`. Throws config::ConfigError.
SeedlingForceModel load_seedling_force_model(const std::string& path);
// Applies [controller]-style overrides (used by the sweep) with the same checks.
void set_operating_point(Scenario& s, double sigma, double depth_mm, double contact_area_mm2);

}  // namespace planter::sim
