#pragma once
// What a run of a plan may disturb beyond the model values (issue 49's disturbance suite):
// the hidden effects, the stems, the clamp law, the soil wheel's slip, the driver, the soil,
// the terrain, the depth target, stops, a silent node, the e-stop, and the paper's own drive
// in place of the sigma loop. Declared once: plan.json names a setting by its key, and a key
// or a value outside its range is refused with the key and the range.
#include <span>
#include <string>

#include "sim/runner/scenario.h"

namespace planter::sim {

struct DisturbanceKey {
  std::string key;  // "effects.force_gain_pct", "route.speed_mps", ...
  double low, high;
  const char* unit;
  const char* what;
  void (*apply)(Scenario&, double);
};

std::span<const DisturbanceKey> disturbance_keys();

// Sets `key` to `value` in `s`. Throws std::runtime_error naming the key and its range.
void apply_disturbance(Scenario& s, const std::string& key, double value);

}  // namespace planter::sim
