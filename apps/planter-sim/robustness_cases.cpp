#include "apps/planter-sim/robustness_cases.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>

#include "apps/planter-sim/latin_hypercube.h"

namespace planter::sim {
namespace {

struct Dimension {  // one axis of the random combinations: from nominal to its top
  const char* key;
  double low, high;
};

// The random combinations' axes; each range runs from the field scenario's value to the
// single cases' value below (assumed tops).
constexpr Dimension kDimensions[] = {
    {"seedlings.diameter_max_mm", 11.4, 15.0},
    {"effects.clamp_stiffness_change_pct", -50.0, 100.0},
    {"effects.force_gain_pct", -20.0, 20.0},
    {"effects.force_offset_N", -5.0, 5.0},
    {"effects.force_drift_N_per_min", -2.0, 2.0},
    {"soil.slip_mean_pct", 3.0, 8.0},
    {"soil.slip_variation_pct", 1.0, 5.0},
    {"route.speed_mps", 0.036, 0.084},
    {"effects.disc_coulomb_Nm", 0.0, 4.0},
    {"effects.command_delay_s", 0.0, 0.1},
    {"effects.depth_sag_mm_per_kN", 0.0, 10.0},
    {"effects.soil_draft_change_pct", -50.0, 150.0},
    {"terrain.roughness_mm", 6.0, 25.0},
    {"effects.clamp_relaxation_frac", 0.0, 0.3},
};

void add_combinations(std::vector<RobustnessCase>& cases, const Scenario& base, double mid_s,
                      int n) {
  if (n <= 0) return;
  constexpr std::size_t k = std::size(kDimensions);
  const auto count = static_cast<std::size_t>(n);
  // As planter-sim montecarlo draws (latin_hypercube.h), seeded by the scenario's seed.
  std::mt19937_64 rng(base.seed ^ 0x6f627573u);
  const std::vector<std::vector<double>> coded = latin_hypercube(count, k, rng);
  for (std::size_t i = 0; i < count; ++i) {
    char name[48];
    std::snprintf(name, sizeof name, "combination %02zu", i + 1);
    RobustnessCase c{name, "all", "every axis drawn between nominal and its top", {}};
    c.settings.emplace_back("effects.change_at_s", mid_s);
    for (std::size_t f = 0; f < k; ++f)
      c.settings.emplace_back(
          kDimensions[f].key,
          kDimensions[f].low + coded[i][f] * (kDimensions[f].high - kDimensions[f].low));
    cases.push_back(std::move(c));
  }
}

}  // namespace

std::vector<RobustnessCase> robustness_cases(const Scenario& base, double distance_m,
                                             int combinations) {
  const double speed = base.plant.route.speed_mps;
  // The middle of the route in time, for the changes that come mid-run.
  const double mid_s = base.plant.start_delay_s + 0.5 * distance_m / speed;
  const double top_speed = base.board.controller.sigma.omega_max_radps *
                           base.board.controller.sigma.disc_radius_m /
                           base.board.controller.sigma.sigma;
  const double end_stop = base.plant.drive.depth_travel_max_mm;
  std::vector<RobustnessCase> c = {
      {"nominal", "all", "the base scenario as it is", {}},
      // Each hidden effect alone, at an assumed top of what a field gives.
      {"disc friction",
       "sigma",
       "Coulomb 4 N*m (assumed: a fifth of the drive's rated torque)",
       {{"effects.disc_coulomb_Nm", 4.0}}},
      {"disc stiction",
       "sigma",
       "Stribeck 2 N*m near standstill (assumed)",
       {{"effects.disc_stribeck_Nm", 2.0}}},
      {"disc dead zone",
       "sigma",
       "0.05 rad/s dead zone of the set-point (assumed)",
       {{"effects.disc_deadzone_radps", 0.05}}},
      {"disc backlash",
       "sigma",
       "2 deg gear play (assumed)",
       {{"effects.disc_backlash_rad", 0.035}}},
      {"command delay",
       "sigma",
       "0.1 s transport delay (assumed)",
       {{"effects.command_delay_s", 0.1}}},
      {"disc drag, all four",
       "sigma",
       "friction, dead zone, backlash and 0.1 s delay together",
       {{"effects.disc_coulomb_Nm", 4.0},
        {"effects.disc_deadzone_radps", 0.05},
        {"effects.disc_backlash_rad", 0.035},
        {"effects.command_delay_s", 0.1}}},
      {"slip with draft",
       "sigma",
       "slip grows 10 %/kN of draft (assumed), draft x2.5",
       {{"effects.slip_per_kN", 10.0}, {"effects.soil_draft_change_pct", 150.0}}},
      {"slip 8 +- 5 %",
       "sigma",
       "slip 8 +- 5 % on a unit calibrated for 3 %",
       {{"soil.slip_mean_pct", 8.0}, {"soil.slip_variation_pct", 5.0}}},
      // For the run with GNSS fitted (the others have no receiver to lose).
      {"slip, GNSS lost 5 s",
       "sigma",
       "slip 8 +- 5 %, and the GNSS fix lost for 5 s mid-row (a tree line)",
       {{"soil.slip_mean_pct", 8.0},
        {"soil.slip_variation_pct", 5.0},
        {"gnss.dropout_at_m", 0.5 * distance_m},
        {"gnss.dropout_s", 5.0}}},
      {"slip, RTK-class GNSS",
       "sigma",
       "slip 8 +- 5 % with a receiver of 0.005 m/s velocity noise (assumed, RTK class)",
       {{"soil.slip_mean_pct", 8.0},
        {"soil.slip_variation_pct", 5.0},
        {"gnss.speed_noise_mps", 0.005}}},
      {"lips relax",
       "clamp",
       "30 % of the lips' force relaxes in 2 s (assumed)",
       {{"effects.clamp_relaxation_frac", 0.3}}},
      {"lips relax slowly",
       "clamp",
       "30 % relaxes in 60 s (assumed)",
       {{"effects.clamp_relaxation2_frac", 0.3}}},
      {"vibration",
       "clamp",
       "30 Hz, 5 N on the force, 3 deg of tilt (assumed)",
       {{"effects.vibration_hz", 30.0},
        {"effects.vibration_force_N", 5.0},
        {"effects.vibration_tilt_deg", 3.0}}},
      {"stiffer lips mid-run",
       "clamp",
       "a batch of lips 100 % stiffer from mid-run",
       {{"effects.change_at_s", mid_s}, {"effects.clamp_stiffness_change_pct", 100.0}}},
      {"softer lips mid-run",
       "clamp",
       "a batch of lips 50 % softer from mid-run",
       {{"effects.change_at_s", mid_s}, {"effects.clamp_stiffness_change_pct", -50.0}}},
      {"thick and thin stems",
       "clamp",
       "stems 5-15 mm",
       {{"seedlings.diameter_min_mm", 5.0}, {"seedlings.diameter_max_mm", 15.0}}},
      {"clamp law far off",
       "clamp",
       "lips F = 30 (x - x0)^1.6 N against the loop's 14.85, 1.3",
       {{"plant.clamp_k_N", 30.0}, {"plant.clamp_n", 1.6}}},
      {"load cell span -20 %", "clamp", "span error -20 %", {{"effects.force_gain_pct", -20.0}}},
      {"load cell span +20 %", "clamp", "span error +20 %", {{"effects.force_gain_pct", 20.0}}},
      {"load cell offset -5 N", "clamp", "offset -5 N", {{"effects.force_offset_N", -5.0}}},
      {"load cell offset +5 N", "clamp", "offset +5 N", {{"effects.force_offset_N", 5.0}}},
      {"load cell drift",
       "clamp",
       "drift -2 N/min (assumed)",
       {{"effects.force_drift_N_per_min", -2.0}}},
      {"load cell all three",
       "clamp",
       "span -20 %, offset -5 N, drift -2 N/min",
       {{"effects.force_gain_pct", -20.0},
        {"effects.force_offset_N", -5.0},
        {"effects.force_drift_N_per_min", -2.0}}},
      {"ground speed -40 %", "sigma", "the driver 40 % slower", {{"route.speed_mps", 0.6 * speed}}},
      {"ground speed +40 %", "sigma", "the driver 40 % faster", {{"route.speed_mps", 1.4 * speed}}},
      {"stops, brisk starts",
       "sigma",
       "two stops, starts and stops at 0.3 m/s^2",
       {{"route.stops", 2.0}, {"route.accel_mps2", 0.3}}},
      {"faster than the disc",
       "sigma",
       "0.30 m/s, past the disc's top speed",
       {{"route.speed_mps", std::max(0.30, 1.25 * top_speed)}}},
      {"harder soil, sag",
       "depth",
       "draft x2.5 from the start, opener sags 10 mm/kN (assumed)",
       {{"effects.soil_draft_change_pct", 150.0}, {"effects.depth_sag_mm_per_kN", 10.0}}},
      {"softer soil, sag",
       "depth",
       "draft x0.5, opener sags 10 mm/kN (assumed)",
       {{"effects.soil_draft_change_pct", -50.0}, {"effects.depth_sag_mm_per_kN", 10.0}}},
      {"sag alone",
       "depth",
       "opener sags 10 mm/kN (assumed)",
       {{"effects.depth_sag_mm_per_kN", 10.0}}},
      {"target near the end stop",
       "depth",
       "depth target 5 mm short of the end stop",
       {{"controller.depth_mm", end_stop - 5.0}}},
      {"terrain 25 mm", "depth", "micro-terrain of 25 mm", {{"terrain.roughness_mm", 25.0}}},
      {"re-engaging",
       "all",
       "a stop with planting switched off and on again",
       {{"route.stops_planting_off", 1.0}}},
      {"roller goes silent",
       "machine",
       "the roller's node stops answering mid-run",
       {{"faults.silent_node", 1.0}, {"faults.silent_at_s", mid_s}}},
      {"e-stop", "machine", "the e-stop pressed mid-run", {{"faults.estop_at_s", mid_s}}},
  };
  add_combinations(c, base, mid_s, combinations);
  return c;
}

}  // namespace planter::sim
