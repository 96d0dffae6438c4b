#include "sim/runner/disturbance_keys.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "sim/plant/effect_keys.h"

namespace planter::sim {
namespace {

// Evenly spaced stops along the route, `planting_off` or not.
void set_stops(Scenario& s, double count, bool planting_off) {
  const auto n = static_cast<int>(std::lround(count));
  for (int i = 1; i <= n; ++i) {
    StopEvent e;
    e.at_m = s.plant.route.distance_m * i / (n + 1);
    // Off and on again needs the disc to stop and the start delay to pass (scenario.cpp).
    e.duration_s = planting_off ? s.plant.start_delay_s + 6.0 : 8.0;
    e.planting_off = planting_off;
    s.plant.route.stops.push_back(e);
  }
}

std::vector<DisturbanceKey> make_keys() {
  std::vector<DisturbanceKey> k;
  // The plant's hidden effects, each over its own range (effect_keys.h).
  for (std::size_t i = 0; i < kEffectKeys.size(); ++i)
    k.push_back({std::string("effects.") + kEffectKeys[i].key, kEffectKeys[i].min,
                 kEffectKeys[i].max, kEffectKeys[i].unit, kEffectKeys[i].what, nullptr});
  const auto add = [&](const char* key, double lo, double hi, const char* unit, const char* what,
                       void (*f)(Scenario&, double)) {
    k.push_back({key, lo, hi, unit, what, f});
  };
  add("seedlings.diameter_min_mm", 1.0, 30.0, "mm", "the thinnest stem",
      [](Scenario& s, double v) { s.plant.seedlings.diameter_min_mm = v; });
  add("seedlings.diameter_max_mm", 1.0, 30.0, "mm", "the thickest stem",
      [](Scenario& s, double v) { s.plant.seedlings.diameter_max_mm = v; });
  add("plant.clamp_k_N", 1.0, 200.0, "N", "the lips' law F = k (x - x0)^n: k",
      [](Scenario& s, double v) { s.plant.drive.clamp_k_N = v; });
  add("plant.clamp_n", 1.0, 3.0, "", "its exponent n",
      [](Scenario& s, double v) { s.plant.drive.clamp_n = v; });
  add("soil.slip_mean_pct", 0.0, 30.0, "%", "the soil wheel's mean slip",
      [](Scenario& s, double v) { s.plant.soil.slip_mean_pct = v; });
  add("soil.slip_variation_pct", 0.0, 20.0, "%", "its variation along the row",
      [](Scenario& s, double v) { s.plant.soil.slip_variation_pct = v; });
  add("route.speed_mps", 0.01, 0.6, "m/s", "the driver's speed",
      [](Scenario& s, double v) { s.plant.route.speed_mps = v; });
  add("route.accel_mps2", 0.005, 2.0, "m/s^2", "the driver's starts and stops",
      [](Scenario& s, double v) { s.plant.route.accel_mps2 = v; });
  add("route.stops", 0.0, 8.0, "", "stops of 8 s, evenly spaced, planting left on",
      [](Scenario& s, double v) { set_stops(s, v, false); });
  add("route.stops_planting_off", 0.0, 8.0, "",
      "stops with planting switched off and on again (re-engaging)",
      [](Scenario& s, double v) { set_stops(s, v, true); });
  add("terrain.roughness_mm", 0.0, 50.0, "mm", "micro-terrain amplitude",
      [](Scenario& s, double v) { s.plant.terrain.roughness_mm = v; });
  add("controller.depth_mm", 20.0, 200.0, "mm", "the depth target (the board's range applies)",
      [](Scenario& s, double v) { s.board.controller.depth.target_mm = v; });
  add("faults.silent_node", 0.0, 3.0, "", "the node that goes silent (node role's index)",
      [](Scenario& s, double v) {
        s.faults.silent_node = node_role_name(static_cast<NodeRole>(std::lround(v)));
      });
  add("faults.silent_at_s", 0.0, 1e5, "s", "when it goes silent",
      [](Scenario& s, double v) { s.faults.silent_at_s = v; });
  add("faults.estop_at_s", 0.0, 1e5, "s", "the e-stop pressed",
      [](Scenario& s, double v) { s.faults.estop_at_s = v; });
  add("faults.estop_release_at_s", 0.0, 1e5, "s", "and released",
      [](Scenario& s, double v) { s.faults.estop_release_at_s = v; });
  add("controller.paper_drive", 0.0, 1.0, "",
      "1: the paper's drive, the disc at a fixed ratio from the soil wheel, in place of the "
      "sigma loop",
      [](Scenario& s, double v) { s.board.controller.sigma.fixed_ratio = v >= 0.5; });
  add("controller.gnss", 0.0, 1.0, "", "1: the simulated GNSS receiver fitted, 0: none",
      [](Scenario& s, double v) { s.board.controller.ground.gnss_fitted = v >= 0.5; });
  add("gnss.speed_noise_mps", 0.0, 5.0, "m/s", "the receiver's velocity noise on each axis",
      [](Scenario& s, double v) { s.plant.gnss.speed_noise_mps = v; });
  add("gnss.dropout_at_m", -1.0, 1e4, "m", "where the fix is lost (-1: never)",
      [](Scenario& s, double v) { s.plant.gnss.dropout_at_m = v; });
  add("gnss.dropout_s", 0.0, 3600.0, "s", "for how long",
      [](Scenario& s, double v) { s.plant.gnss.dropout_s = v; });
  return k;
}

}  // namespace

std::span<const DisturbanceKey> disturbance_keys() {
  static const std::vector<DisturbanceKey> keys = make_keys();
  return keys;
}

void apply_disturbance(Scenario& s, const std::string& key, double value) {
  const auto keys = disturbance_keys();
  const auto it =
      std::find_if(keys.begin(), keys.end(), [&](const DisturbanceKey& k) { return k.key == key; });
  if (it == keys.end())
    throw std::runtime_error("the plan disturbs '" + key + "', which is no disturbance key");
  if (!std::isfinite(value) || value < it->low || value > it->high)
    throw std::runtime_error("the plan sets '" + key + "' to " + std::to_string(value) +
                             ": allowed " + std::to_string(it->low) + " to " +
                             std::to_string(it->high) + " " + it->unit);
  if (it->apply) {
    it->apply(s, value);
    return;
  }
  const std::size_t i = static_cast<std::size_t>(it - keys.begin());  // an effect's index
  s.plant.effects.*kEffectKeys[i].member = value;
}

}  // namespace planter::sim
