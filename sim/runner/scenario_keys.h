#pragma once
// The keys of a scenario and of a seedling force model, declared once (config/config_key.h).
// The loader (sim/runner/scenario.cpp) reads through these rows; `planter-sim --list-keys` and
// docs/configuration.md print them. Defaults the plant's structs hold are taken from there.
#include <array>
#include <cstdint>

#include "config/config_key.h"
#include "sim/plant/effect_keys.h"
#include "sim/plant/plant_config.h"

namespace planter::sim {

using config::bool_key;
using config::integer_key;
using config::kNoDefault;
using config::number_key;
using config::required_number_key;
using config::retired_key;
using config::string_key;
using config::table_key;
using config::FileKind::kScenario;
using config::FileKind::kSeedlingForce;

// clang-format off
inline constexpr config::ConfigKey kScenarioKeys[] = {
  string_key(kScenario, "scenario", "name", "", "the scenario's name in reports (unset: the file's name)"),
  string_key(kScenario, "scenario", "board", "", "the board file the simulated machine runs, relative to the scenario", true),
  integer_key(kScenario, "scenario", "seed", 1, 0, static_cast<double>(INT64_MAX), "", "the random seed: the same seed gives the same run"),
  number_key(kScenario, "scenario", "tail_s", 3.0, 0.0, 600.0, "s", "how long the run goes on after the machine reached the end"),
  number_key(kScenario, "scenario", "max_duration_s", 3600.0, 1.0, 86400.0, "s", "the run stops here whatever happens"),
  number_key(kScenario, "scenario", "start_delay_s", 3.0, 0.0, 600.0, "s", "the operator presses start this long after power-up"),
  number_key(kScenario, "route", "distance_m", RouteConfig{}.distance_m, 0.1, 10000.0, "m", "the row's length"),
  number_key(kScenario, "route", "speed_mps", RouteConfig{}.speed_mps, 0.005, 1.0, "m/s", "the tractor's forward speed"),
  number_key(kScenario, "route", "accel_mps2", RouteConfig{}.accel_mps2, 0.001, 5.0, "m/s^2", "the tractor's acceleration from rest"),
  number_key(kScenario, "route", "speed_variation_pct", RouteConfig{}.speed_variation_pct, 0.0, 50.0, "%", "a slow sinusoidal variation of the driver's speed"),
  number_key(kScenario, "route", "speed_variation_period_s", RouteConfig{}.speed_variation_period_s, 0.5, 1000.0, "s", "its period"),
  table_key(kScenario, "route", "stops", "stops along the row, each a [[route.stops]] table (at most 32)"),
  number_key(kScenario, "route.stops[]", "at_m", 0.0, 0.0, 10000.0, "m", "where the tractor stops (at most distance_m)"),
  number_key(kScenario, "route.stops[]", "duration_s", 5.0, 0.0, 3600.0, "s", "how long it stands"),
  bool_key(kScenario, "route.stops[]", "planting_off", false, "the operator switches planting off for the stop (at least start_delay_s + 5 s)"),
  number_key(kScenario, "route", "push_at_s", RouteConfig{}.push_at_s, -1.0, 1e6, "s", "commissioning: the machine is pushed along from this time, controller or not (-1: never)"),
  number_key(kScenario, "terrain", "roughness_mm", TerrainConfig{}.roughness_mm, 0.0, 100.0, "mm", "the micro-terrain's amplitude"),
  number_key(kScenario, "terrain", "wavelength_m", TerrainConfig{}.wavelength_m, 0.01, 100.0, "m", "its wavelength"),
  number_key(kScenario, "terrain", "depth_share", TerrainConfig{}.depth_share, 0.0, 1.0, "", "the share of the terrain's height the furrow depth takes (assumed, 0.1-0.6)"),
  number_key(kScenario, "soil", "wheel_radius_m", SoilConfig{}.wheel_radius_m, 0.02, 1.0, "m", "the soil wheel's true radius"),
  number_key(kScenario, "soil", "slip_mean_pct", SoilConfig{}.slip_mean_pct, -20.0, 50.0, "%", "the towed soil wheel's mean travel reduction"),
  number_key(kScenario, "soil", "slip_variation_pct", SoilConfig{}.slip_variation_pct, 0.0, 20.0, "%", "its slow sinusoidal variation along the row"),
  number_key(kScenario, "soil", "slip_variation_wavelength_m", SoilConfig{}.slip_variation_wavelength_m, 0.1, 1000.0, "m", "that variation's wavelength (assumed, 1-20 m)"),
  string_key(kScenario, "soil", "texture", "medium", "fine, medium or coarse: the texture factor F_i of ASABE D497's draft"),
  number_key(kScenario, "soil", "draft_a_N_per_cm", soil::OpenerDraftLaw{}.a_N_per_cm, 0.0, 1e4, "N/cm", "D497's A: the opener draft's speed-independent part per cm of depth"),
  number_key(kScenario, "soil", "draft_b_N_per_cm_kmh", soil::OpenerDraftLaw{}.b_N_per_cm_kmh, 0.0, 1e4, "N/(cm km/h)", "D497's B"),
  number_key(kScenario, "soil", "draft_c_N_per_cm_kmh2", soil::OpenerDraftLaw{}.c_N_per_cm_kmh2, 0.0, 1e4, "N/(cm (km/h)^2)", "D497's C"),
  number_key(kScenario, "soil", "draft_depth_exponent", soil::OpenerDraftLaw{}.depth_exponent, 1.0, 2.0, "", "the draft's exponent on depth"),
  number_key(kScenario, "soil", "unit_weight_kN_per_m3", SoilConfig{}.backflow.unit_weight_kN_per_m3, 5.0, 25.0, "kN/m^3", "the loose soil's unit weight, holding the planted root"),
  number_key(kScenario, "soil", "friction_angle_deg", SoilConfig{}.backflow.friction_angle_deg, 10.0, 50.0, "deg", "the soil's friction angle (loose and firmed)"),
  number_key(kScenario, "soil", "cohesion_kPa", SoilConfig{}.backflow.cohesion_kPa, 0.0, 100.0, "kPa", "the loose soil's apparent cohesion"),
  number_key(kScenario, "soil", "firmed_unit_weight_kN_per_m3", SoilConfig{}.firmed.unit_weight_kN_per_m3, 5.0, 25.0, "kN/m^3", "the soil's unit weight once the covering wheel pressed it"),
  number_key(kScenario, "soil", "firmed_cohesion_kPa", SoilConfig{}.firmed.cohesion_kPa, 0.0, 100.0, "kPa", "its cohesion then"),
  retired_key(kScenario, "soil", "draft_coeff", "was c_s in a draft proportional to speed, which was wrong; the draft now has ASABE D497's form: set texture and, if measured, draft_a_N_per_cm (docs/simulator.md, \"Model assumptions\")"),
  number_key(kScenario, "seedlings", "length_min_mm", SeedlingSpread{}.length_min_mm, 50.0, 500.0, "mm", "the shortest seedling"),
  number_key(kScenario, "seedlings", "length_max_mm", SeedlingSpread{}.length_max_mm, 50.0, 500.0, "mm", "the longest (at least length_min_mm)"),
  number_key(kScenario, "seedlings", "diameter_min_mm", SeedlingSpread{}.diameter_min_mm, 2.0, 30.0, "mm", "the thinnest stem"),
  number_key(kScenario, "seedlings", "diameter_max_mm", SeedlingSpread{}.diameter_max_mm, 2.0, 30.0, "mm", "the thickest (at least diameter_min_mm)"),
  number_key(kScenario, "seedlings", "feed_miss_pct", SeedlingSpread{}.feed_miss_pct, 0.0, 100.0, "%", "clamps the feed leaves empty"),
  number_key(kScenario, "seedlings", "feed_double_pct", SeedlingSpread{}.feed_double_pct, 0.0, 100.0, "%", "clamps the feed fills with two (at most 100 - feed_miss_pct)"),
  number_key(kScenario, "seedlings", "strength_mean_N", kNoDefault, 10.0, 1000.0, "N", "the seedlings' mean crushing strength (unset: the paper's measured peaks)", "measured"),
  number_key(kScenario, "seedlings", "strength_sd_N", kNoDefault, 0.0, 500.0, "N", "its standard deviation (unset: the measured peaks')", "measured"),
  number_key(kScenario, "seedlings", "strength_diameter_exponent", SeedlingSpread{}.strength_diameter_exponent, -3.0, 3.0, "", "strength grows as (diameter / reference)^k (assumed, no measurement)"),
  number_key(kScenario, "seedlings", "strength_test_length_mm", SeedlingSpread{}.strength_test_length_mm, 1.0, 200.0, "mm", "the stem length the strength test's plates loaded (assumed)"),
  number_key(kScenario, "seedlings", "tilt_noise_deg", SeedlingSpread{}.tilt_noise_deg, 0.0, 45.0, "deg", "tilt scatter the release mechanics leave out (calibrated to the paper's centre point)"),
  number_key(kScenario, "seedlings", "density_kg_per_m3", SeedlingSpread{}.density_kg_per_m3, 100.0, 2000.0, "kg/m^3", "the seedling's density (the paper's Table 2)"),
  string_key(kScenario, "seedlings", "force_model", "", "a seedling force model from planter-dem reduce, relative to the scenario (unset: none)"),
  retired_key(kScenario, "seedlings", "feed_pitch_mm", "is the machine's: [planting_monitor] clamp_pitch_mm in machines/<machine>.toml (the planting monitor's target spacing comes from it too)"),
  number_key(kScenario, "mechanism", "contact_area_mm2", MechanismConfig{}.contact_area_mm2, 50.0, 600.0, "mm^2", "the lips' contact area on the seedling"),
  number_key(kScenario, "mechanism", "carry_angle_deg", MechanismConfig{}.carry_angle_deg, 30.0, 300.0, "deg", "the disc's turn from pickup to release"),
  number_key(kScenario, "mechanism", "release_after_lowest_deg", MechanismConfig{}.release_after_lowest_deg, -60.0, 60.0, "deg", "where the lips open, past the lowest point (set once, no source)"),
  number_key(kScenario, "mechanism", "root_clearance_mm", MechanismConfig{}.root_clearance_mm, 0.0, 100.0, "mm", "the root end's lowest point above the furrow floor (assumed)"),
  number_key(kScenario, "mechanism", "covering_wheel_behind_mm", MechanismConfig{}.covering_wheel_behind_mm, 0.0, 2000.0, "mm", "the covering wheel's distance behind the release (assumed)"),
  number_key(kScenario, "mechanism", "handoff_speed_mismatch_mps", MechanismConfig{}.handoff_speed_mismatch_mps, 0.0, 2.0, "m/s", "the belt's speed against the lips' at the hand-off (assumed)"),
  number_key(kScenario, "mechanism", "protrusion_band_mm", MechanismConfig{}.protrusion_band_mm, 5.0, 200.0, "mm", "the band of flexible protrusions on the lips (the paper, Sec. 3.1)"),
  number_key(kScenario, "mechanism", "nip_time_s", MechanismConfig{}.nip_time_s, 0.01, 5.0, "s", "how long a seedling stays in the roller nip"),
  number_key(kScenario, "mechanism", "nip_entry_mm", MechanismConfig{}.nip_entry_mm, 0.0, 100.0, "mm", "the rim's travel over which the lips close on a stem and open again (the paper's 20 mm roller's radius; 0: at once)"),
  number_key(kScenario, "mechanism", "residual_grip_share", MechanismConfig{}.residual_grip_share, 0.0, 1.0, "", "the lip pressure left after release, of the clamp's (set once, no source)"),
  number_key(kScenario, "mechanism", "root_protrusion_mm", MechanismConfig{}.root_protrusion_mm, 10.0, 200.0, "mm", "the root end beyond the disc rim (assumed)"),
  number_key(kScenario, "mechanism", "lip_friction", MechanismConfig{}.lip_friction, 0.0, 2.0, "", "seedling on silicone rubber (the paper's 0.2-0.3)"),
  number_key(kScenario, "mechanism", "lip_shear_modulus_MPa", MechanismConfig{}.lip_shear_modulus_MPa, 0.01, 100.0, "MPa", "the lips' rubber in shear (assumed)"),
  number_key(kScenario, "mechanism", "lip_shear_layer_mm", MechanismConfig{}.lip_shear_layer_mm, 0.5, 100.0, "mm", "the sheared rubber's thickness (assumed)"),
  number_key(kScenario, "mechanism", "backflow_fill", MechanismConfig{}.backflow_fill, 0.0, 1.0, "", "the share of the furrow refilled at the seedling (assumed)"),
  retired_key(kScenario, "mechanism", "release_angle_deg", "belonged to the tilt formula the release mechanics replaced; the release is set by release_after_lowest_deg, root_clearance_mm, residual_grip_share, root_protrusion_mm and lip_friction"),
  retired_key(kScenario, "mechanism", "kinematic_gain", "belonged to the tilt formula the release mechanics replaced; the release is set by release_after_lowest_deg, root_clearance_mm, residual_grip_share, root_protrusion_mm and lip_friction"),
  retired_key(kScenario, "mechanism", "optimum_sigma", "belonged to the tilt formula the release mechanics replaced; the release is set by release_after_lowest_deg, root_clearance_mm, residual_grip_share, root_protrusion_mm and lip_friction"),
  retired_key(kScenario, "mechanism", "root_reach_mm", "was typed to the paper's optimum depth and is gone: the disc rides with the opener, so the root's reach follows from the depth and root_clearance_mm"),
  number_key(kScenario, "plant", "disc_time_constant_s", DriveModelConfig{}.disc_time_constant_s, 0.001, 5.0, "s", "the disc drive's speed loop time constant"),
  number_key(kScenario, "plant", "disc_inertia_kgm2", DriveModelConfig{}.disc_inertia_kgm2, 1e-4, 100.0, "kg*m^2", "the disc's inertia"),
  number_key(kScenario, "plant", "disc_damping_Nms", DriveModelConfig{}.disc_damping_Nms, 0.0, 1000.0, "N*m*s", "the disc's viscous damping"),
  number_key(kScenario, "plant", "actuator_time_constant_s", DriveModelConfig{}.actuator_time_constant_s, 0.001, 5.0, "s", "the roller and depth actuators' time constant"),
  number_key(kScenario, "plant", "clamp_k_N", DriveModelConfig{}.clamp_k_N, 0.1, 1e4, "N", "the true clamp law's stiffness, F = k (x - x0)^n"),
  number_key(kScenario, "plant", "clamp_x0_mm", DriveModelConfig{}.clamp_x0_mm, 0.0, 50.0, "mm", "its free travel"),
  number_key(kScenario, "plant", "clamp_n", DriveModelConfig{}.clamp_n, 1.0, 3.0, "", "its exponent"),
  number_key(kScenario, "plant", "force_noise_N", DriveModelConfig{}.force_noise_N, 0.0, 50.0, "N", "the load cell's noise"),
  number_key(kScenario, "plant", "depth_travel_max_mm", DriveModelConfig{}.depth_travel_max_mm, 10.0, 500.0, "mm", "the opener actuator's mechanical end stop"),
  number_key(kScenario, "gnss", "rate_hz", GnssConfig{}.rate_hz, 0.2, 50.0, "Hz", "the simulated receiver's fixes a second (a datasheet's: 1-10 Hz)"),
  number_key(kScenario, "gnss", "speed_noise_mps", GnssConfig{}.speed_noise_mps, 0.0, 5.0, "m/s", "its velocity noise on each horizontal axis, 1 sigma (u-blox NEO-M8: 0.05)"),
  number_key(kScenario, "gnss", "latency_s", GnssConfig{}.latency_s, 0.0, 2.0, "s", "from a fix's measurement to the controller (assumed, 0.02-0.1)"),
  integer_key(kScenario, "gnss", "satellites", GnssConfig{}.satellites, 0, 64, "", "satellites in the fix (assumed, open sky 8-20)"),
  number_key(kScenario, "gnss", "hdop", GnssConfig{}.hdop, 0.1, 99.0, "", "the fix's horizontal dilution of precision (assumed, open sky 0.6-1.5)"),
  number_key(kScenario, "gnss", "dropout_at_m", GnssConfig{}.dropout_at_m, -1.0, 10000.0, "m", "the fix is lost here along the row (-1: never)"),
  number_key(kScenario, "gnss", "dropout_s", GnssConfig{}.dropout_s, 0.0, 3600.0, "s", "for this long"),
  number_key(kScenario, "gnss", "origin_lat_deg", GnssConfig{}.origin_lat_deg, -89.0, 89.0, "deg", "where the row starts"),
  number_key(kScenario, "gnss", "origin_lon_deg", GnssConfig{}.origin_lon_deg, -180.0, 180.0, "deg", "where the row starts"),
  number_key(kScenario, "gnss", "heading_deg", GnssConfig{}.heading_deg, 0.0, 360.0, "deg", "the row's direction, clockwise from north"),
  number_key(kScenario, "gnss", "position_noise_m", GnssConfig{}.position_noise_m, 0.0, 100.0, "m", "the fix's position noise on each axis, 1 sigma (assumed, standalone 0.5-3)"),
  table_key(kScenario, "", "effects", "effects hidden in the plant, each off unless set (the [effects] rows below)"),
  number_key(kScenario, "controller", "sigma", kNoDefault, 0.5, 3.0, "", "overrides the machine's sigma", "the machine's"),
  bool_key(kScenario, "controller", "clamp_per_stem_grip", false, "overrides the machine's clamp_per_stem_grip (false: one set-point for every stem)", "the machine's"),
  bool_key(kScenario, "controller", "gnss", false, "overrides the board's GNSS receiver: true fits the simulated one ([gnss] below), false takes it off", "the board's"),
  number_key(kScenario, "controller", "clamp_force_N", kNoDefault, 0.0, 200.0, "N", "overrides the machine's clamp force (below its derived ceiling)", "the machine's"),
  number_key(kScenario, "controller", "depth_mm", kNoDefault, 40.0, 160.0, "mm", "overrides the machine's furrow depth", "the machine's"),
  number_key(kScenario, "faults", "estop_at_s", -1.0, -1.0, 1e6, "s", "the e-stop is pressed at this time (-1: never)"),
  number_key(kScenario, "faults", "estop_release_at_s", -1.0, -1.0, 1e6, "s", "and released at this time (-1: never)"),
  string_key(kScenario, "faults", "silent_node", "", "a node that stops answering: disc_drive, roller_actuator, depth_actuator or force_sensor"),
  number_key(kScenario, "faults", "silent_at_s", -1.0, -1.0, 1e6, "s", "when it falls silent (-1: never)"),
};

// [effects]: the rows of sim/plant/effect_keys.h, as configuration keys.
inline constexpr auto kScenarioEffectKeys = [] {
  std::array<config::ConfigKey, kEffectKeys.size()> rows{};
  for (std::size_t i = 0; i < kEffectKeys.size(); ++i) {
    const EffectKey& e = kEffectKeys[i];
    rows[i] = number_key(kScenario, "effects", e.key, e.fallback, e.min, e.max, e.unit, e.what);
  }
  return rows;
}();

inline constexpr config::ConfigKey kSeedlingForceKeys[] = {
  required_number_key(kSeedlingForce, "seedling_force", "reference_diameter_mm", 3.0, 30.0, "mm", "the stem diameter the law's figures are for"),
  required_number_key(kSeedlingForce, "seedling_force", "exponent", 0.5, 4.0, "", "n in F = k x^n"),
  required_number_key(kSeedlingForce, "seedling_force", "stiffness_N_per_mm_n", 1e-3, 1e5, "N/mm^n", "k at the reference diameter"),
  required_number_key(kSeedlingForce, "seedling_force", "stiffness_slope_per_mm", -1e5, 1e5, "", "k's change per mm of diameter"),
  required_number_key(kSeedlingForce, "seedling_force", "peak_force_N", 1.0, 1e4, "N", "the first peak's force at the reference diameter"),
  required_number_key(kSeedlingForce, "seedling_force", "peak_force_slope_N_per_mm", -1e4, 1e4, "N/mm", "its change per mm of diameter"),
  required_number_key(kSeedlingForce, "seedling_force", "peak_displacement_mm", 0.05, 20.0, "mm", "the compression at the first peak"),
  required_number_key(kSeedlingForce, "seedling_force", "peak_displacement_slope", -10.0, 10.0, "", "its change per mm of diameter"),
  required_number_key(kSeedlingForce, "seedling_force", "residual_fraction", 0.0, 1.0, "", "the force left after the peak, of the peak's"),
  required_number_key(kSeedlingForce, "seedling_force", "damping_N_s_per_mm", 0.0, 1e4, "N*s/mm", "the stem's viscous damping"),
};
// clang-format on

// A scenario's rows, then a seedling force model's, as `planter-sim --list-keys` prints them.
inline constexpr std::span<const config::ConfigKey> kScenarioFileKeys[] = {
    kScenarioKeys, kScenarioEffectKeys, kSeedlingForceKeys};

}  // namespace planter::sim
