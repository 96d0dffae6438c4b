#include "sim/runner/scenario.h"

#include <filesystem>

#include "config/board_keys.h"
#include "config/toml_section.h"
#include "sim/plant/effect_keys.h"
#include "sim/runner/scenario_keys.h"

namespace planter::sim {

using config::ConfigError;
using config::TomlSection;

namespace {

consteval const config::ConfigKey& sk(std::string_view dotted) {
  return config::key_in(kScenarioKeys, dotted);
}
consteval const config::ConfigKey& fk(std::string_view dotted) {
  return config::key_in(kSeedlingForceKeys, dotted);
}

// A scenario's rows and the board files' (a machine key in a scenario says where it belongs).
inline constexpr std::span<const config::ConfigKey> kKnownKeys[] = {
    kScenarioKeys,      kScenarioEffectKeys,  kSeedlingForceKeys,
    config::kBoardKeys, config::kMachineKeys, config::kCalibrationKeys};

config::KeyTables key_tables(config::FileKind here) { return {here, kKnownKeys}; }

}  // namespace

SeedlingForceModel load_seedling_force_model(const std::string& path) {
  config::TomlDocument doc(path, key_tables(config::FileKind::kSeedlingForce));
  TomlSection root = doc.root();
  auto t = root.table("seedling_force");
  if (!t) throw ConfigError(path, 1, "seedling_force", "table is missing (planter-dem reduce)");
  SeedlingForceModel m;
  m.reference_diameter_mm = t->number(fk("seedling_force.reference_diameter_mm"));
  m.exponent = t->number(fk("seedling_force.exponent"));
  m.stiffness_N_per_mm_n = t->number(fk("seedling_force.stiffness_N_per_mm_n"));
  m.stiffness_slope_per_mm = t->number(fk("seedling_force.stiffness_slope_per_mm"));
  m.peak_force_N = t->number(fk("seedling_force.peak_force_N"));
  m.peak_force_slope_N_per_mm = t->number(fk("seedling_force.peak_force_slope_N_per_mm"));
  m.peak_displacement_mm = t->number(fk("seedling_force.peak_displacement_mm"));
  m.peak_displacement_slope = t->number(fk("seedling_force.peak_displacement_slope"));
  m.residual_fraction = t->number(fk("seedling_force.residual_fraction"));
  m.damping_N_s_per_mm = t->number(fk("seedling_force.damping_N_s_per_mm"));
  t->reject_unknown_keys();
  root.reject_unknown_keys();
  m.loaded = true;
  return m;
}

namespace {

// [route]: distance, speed and its variation, the stops.
void read_route(TomlSection& r, PlantConfig& p) {
  p.route.distance_m = r.number(sk("route.distance_m"));
  p.route.speed_mps = r.number(sk("route.speed_mps"));
  p.route.accel_mps2 = r.number(sk("route.accel_mps2"));
  p.route.speed_variation_pct = r.number(sk("route.speed_variation_pct"));
  p.route.speed_variation_period_s = r.number(sk("route.speed_variation_period_s"));
  for (auto& stop : r.array_of_tables("stops")) {
    StopEvent e;
    e.at_m = stop.number(sk("route.stops[].at_m"));
    if (e.at_m > p.route.distance_m)
      stop.fail(sk("route.stops[].at_m"), "must not be beyond route.distance_m");
    e.duration_s = stop.number(sk("route.stops[].duration_s"));
    e.planting_off = stop.boolean(sk("route.stops[].planting_off"));
    // Off and on again needs the disc to stop and the start delay to pass within the stop.
    if (e.planting_off && e.duration_s < p.start_delay_s + 5.0)
      stop.fail(sk("route.stops[].duration_s"),
                "must be at least start_delay_s + 5 s with planting_off = true");
    stop.reject_unknown_keys();
    p.route.stops.push_back(e);
  }
  if (p.route.stops.size() > 32) r.fail(sk("route.stops"), "at most 32 stops");
  p.route.push_at_s = r.number(sk("route.push_at_s"));
  r.reject_unknown_keys();
}

// [terrain]: the terrain under the depth wheel.
void read_terrain(TomlSection& t, PlantConfig& p) {
  p.terrain.roughness_mm = t.number(sk("terrain.roughness_mm"));
  p.terrain.wavelength_m = t.number(sk("terrain.wavelength_m"));
  p.terrain.depth_share = t.number(sk("terrain.depth_share"));
  t.reject_unknown_keys();
}

// [soil]: the wheel, its slip, the opener's draft (ASABE D497) and the backflow.
void read_soil(TomlSection& t, PlantConfig& p) {
  p.soil.wheel_radius_m = t.number(sk("soil.wheel_radius_m"));
  p.soil.slip_mean_pct = t.number(sk("soil.slip_mean_pct"));
  p.soil.slip_variation_pct = t.number(sk("soil.slip_variation_pct"));
  p.soil.slip_variation_wavelength_m = t.number(sk("soil.slip_variation_wavelength_m"));
  soil::OpenerDraftLaw& d = p.soil.draft;
  const std::string texture = t.string(sk("soil.texture"));
  d.texture_factor = soil::texture_factor_of(texture);
  if (d.texture_factor < 0.0)
    t.fail(sk("soil.texture"), "is '" + texture + "'; allowed: fine, medium, coarse (D497's F_i)");
  d.a_N_per_cm = t.number(sk("soil.draft_a_N_per_cm"));
  d.b_N_per_cm_kmh = t.number(sk("soil.draft_b_N_per_cm_kmh"));
  d.c_N_per_cm_kmh2 = t.number(sk("soil.draft_c_N_per_cm_kmh2"));
  d.depth_exponent = t.number(sk("soil.draft_depth_exponent"));
  soil::Soil& g = p.soil.backflow;
  soil::Soil& f = p.soil.firmed;
  g.unit_weight_kN_per_m3 = t.number(sk("soil.unit_weight_kN_per_m3"));
  g.friction_angle_deg = t.number(sk("soil.friction_angle_deg"));
  f.friction_angle_deg = g.friction_angle_deg;
  g.cohesion_kPa = t.number(sk("soil.cohesion_kPa"));
  f.unit_weight_kN_per_m3 = t.number(sk("soil.firmed_unit_weight_kN_per_m3"));
  f.cohesion_kPa = t.number(sk("soil.firmed_cohesion_kPa"));
  t.reject_unknown_keys();
}

// [seedlings]: their sizes, the feed's misses and doubles, their strength and force
// model.
void read_seedlings(TomlSection& t, const std::string& path, PlantConfig& p) {
  SeedlingConfig& c = p.seedlings;
  c.length_min_mm = t.number(sk("seedlings.length_min_mm"));
  c.length_max_mm = t.number(sk("seedlings.length_max_mm"));
  if (c.length_max_mm < c.length_min_mm)
    t.fail(sk("seedlings.length_max_mm"), "must be at least length_min_mm");
  c.diameter_min_mm = t.number(sk("seedlings.diameter_min_mm"));
  c.diameter_max_mm = t.number(sk("seedlings.diameter_max_mm"));
  if (c.diameter_max_mm < c.diameter_min_mm)
    t.fail(sk("seedlings.diameter_max_mm"), "must be at least diameter_min_mm");
  c.feed_miss_pct = t.number(sk("seedlings.feed_miss_pct"));
  c.feed_double_pct = t.number(sk("seedlings.feed_double_pct"));
  if (c.feed_double_pct > 100.0 - c.feed_miss_pct)
    t.fail(sk("seedlings.feed_double_pct"), "must be at most 100 - feed_miss_pct");
  // Unset: the measured peaks' (config/stem_strength.h).
  if (t.has(sk("seedlings.strength_mean_N")))
    c.strength_mean_N = t.number(sk("seedlings.strength_mean_N"));
  if (t.has(sk("seedlings.strength_sd_N")))
    c.strength_sd_N = t.number(sk("seedlings.strength_sd_N"));
  c.strength_diameter_exponent = t.number(sk("seedlings.strength_diameter_exponent"));
  c.strength_test_length_mm = t.number(sk("seedlings.strength_test_length_mm"));
  c.tilt_noise_deg = t.number(sk("seedlings.tilt_noise_deg"));
  c.density_kg_per_m3 = t.number(sk("seedlings.density_kg_per_m3"));
  const std::string model = t.string(sk("seedlings.force_model"));
  if (!model.empty()) {
    const auto model_path = std::filesystem::path(path).parent_path() / model;
    if (!std::filesystem::exists(model_path))
      t.fail(sk("seedlings.force_model"), "file " + model_path.string() + " does not exist");
    c.force_model = load_seedling_force_model(model_path.string());
    c.force_model_file = model;
  }
  t.reject_unknown_keys();
}

// [mechanism]: the disc's clamp, its nip and release.
void read_mechanism(TomlSection& t, PlantConfig& p) {
  MechanismConfig& m = p.mechanism;
  m.contact_area_mm2 = t.number(sk("mechanism.contact_area_mm2"));
  m.carry_angle_deg = t.number(sk("mechanism.carry_angle_deg"));
  m.release_after_lowest_deg = t.number(sk("mechanism.release_after_lowest_deg"));
  m.root_clearance_mm = t.number(sk("mechanism.root_clearance_mm"));
  m.covering_wheel_behind_mm = t.number(sk("mechanism.covering_wheel_behind_mm"));
  m.handoff_speed_mismatch_mps = t.number(sk("mechanism.handoff_speed_mismatch_mps"));
  m.protrusion_band_mm = t.number(sk("mechanism.protrusion_band_mm"));
  m.nip_time_s = t.number(sk("mechanism.nip_time_s"));
  m.nip_entry_mm = t.number(sk("mechanism.nip_entry_mm"));
  m.residual_grip_share = t.number(sk("mechanism.residual_grip_share"));
  m.root_protrusion_mm = t.number(sk("mechanism.root_protrusion_mm"));
  m.lip_friction = t.number(sk("mechanism.lip_friction"));
  m.lip_shear_modulus_MPa = t.number(sk("mechanism.lip_shear_modulus_MPa"));
  m.lip_shear_layer_mm = t.number(sk("mechanism.lip_shear_layer_mm"));
  m.backflow_fill = t.number(sk("mechanism.backflow_fill"));
  t.reject_unknown_keys();
}

// [plant]: the drives' and the clamp's own laws.
void read_plant(TomlSection& t, PlantConfig& p) {
  DriveModelConfig& d = p.drive;
  d.disc_time_constant_s = t.number(sk("plant.disc_time_constant_s"));
  d.disc_inertia_kgm2 = t.number(sk("plant.disc_inertia_kgm2"));
  d.disc_damping_Nms = t.number(sk("plant.disc_damping_Nms"));
  d.actuator_time_constant_s = t.number(sk("plant.actuator_time_constant_s"));
  d.clamp_k_N = t.number(sk("plant.clamp_k_N"));
  d.clamp_x0_mm = t.number(sk("plant.clamp_x0_mm"));
  d.clamp_n = t.number(sk("plant.clamp_n"));
  d.force_noise_N = t.number(sk("plant.force_noise_N"));
  d.depth_travel_max_mm = t.number(sk("plant.depth_travel_max_mm"));
  t.reject_unknown_keys();
}

// [gnss]: the GNSS receiver.
void read_gnss(TomlSection& t, PlantConfig& p) {
  GnssConfig& g = p.gnss;
  g.rate_hz = t.number(sk("gnss.rate_hz"));
  g.speed_noise_mps = t.number(sk("gnss.speed_noise_mps"));
  g.latency_s = t.number(sk("gnss.latency_s"));
  g.satellites = static_cast<int>(t.integer(sk("gnss.satellites")));
  g.hdop = t.number(sk("gnss.hdop"));
  g.dropout_at_m = t.number(sk("gnss.dropout_at_m"));
  g.dropout_s = t.number(sk("gnss.dropout_s"));
  g.origin_lat_deg = t.number(sk("gnss.origin_lat_deg"));
  g.origin_lon_deg = t.number(sk("gnss.origin_lon_deg"));
  g.heading_deg = t.number(sk("gnss.heading_deg"));
  g.position_noise_m = t.number(sk("gnss.position_noise_m"));
  t.reject_unknown_keys();
}

// [effects]: the physics hidden in the plant (docs/adding-an-effect.md).
void read_effects(TomlSection& t, PlantConfig& p) {
  Effects& e = p.effects;
  for (std::size_t i = 0; i < kEffectKeys.size(); ++i)
    e.*kEffectKeys[i].member = t.number(kScenarioEffectKeys[i]);
  if (e.clamp_relaxation_frac + e.clamp_relaxation2_frac > 0.9)
    t.fail(config::key_in(kScenarioEffectKeys, "effects.clamp_relaxation2_frac"),
           "with clamp_relaxation_frac must stay at most 0.9 (the branches share the load)");
  t.reject_unknown_keys();
}

// [controller]: operating-point overrides of the board's [control] table.
void read_controller(TomlSection& t, Scenario& s) {
  auto& c = s.board.controller;
  c.sigma.sigma = t.number(sk("controller.sigma"), c.sigma.sigma);
  c.clamp.setpoint_N = t.number(sk("controller.clamp_force_N"), c.clamp.setpoint_N);
  c.clamp.per_stem_grip = t.boolean(sk("controller.clamp_per_stem_grip"), c.clamp.per_stem_grip);
  c.ground.gnss_fitted = t.boolean(sk("controller.gnss"), c.ground.gnss_fitted);
  if (c.clamp.setpoint_N >= c.clamp.ceiling_N)
    t.fail(sk("controller.clamp_force_N"),
           "must be below the machine's " +
               config::clamp_ceiling_derivation(s.board.clamp_ceiling,
                                                c.clamp.stem.reference_diameter_mm));
  c.depth.target_mm = t.number(sk("controller.depth_mm"), c.depth.target_mm);
  t.reject_unknown_keys();
}

// [faults]: the faults injected, the e-stop, a silent node.
void read_faults(TomlSection& t, Scenario& s) {
  s.faults.estop_at_s = t.number(sk("faults.estop_at_s"));
  s.faults.estop_release_at_s = t.number(sk("faults.estop_release_at_s"));
  s.faults.silent_node = t.string(sk("faults.silent_node"));
  if (!s.faults.silent_node.empty()) {
    bool known = false;
    for (std::size_t i = 0; i < kNodeCount; ++i)
      known = known || s.faults.silent_node == node_role_name(static_cast<NodeRole>(i));
    if (!known)
      t.fail(sk("faults.silent_node"),
             "must be one of disc_drive, roller_actuator, depth_actuator, force_sensor");
  }
  s.faults.silent_at_s = t.number(sk("faults.silent_at_s"));
  t.reject_unknown_keys();
}

}  // namespace

Scenario load_scenario(const std::string& path) {
  config::TomlDocument doc(path, key_tables(config::FileKind::kScenario));
  TomlSection root = doc.root();
  Scenario s;
  s.file = path;
  auto sc = root.table("scenario");
  if (!sc) throw ConfigError(path, 1, "scenario", "table is missing (name, board, seed)");
  s.name = sc->string(sk("scenario.name"), std::filesystem::path(path).stem().string());
  const std::string board = sc->string(sk("scenario.board"));
  if (board.empty())
    sc->fail(sk("scenario.board"), "is required: path of a board file, relative to the scenario");
  const auto board_path = std::filesystem::path(path).parent_path() / board;
  if (!std::filesystem::exists(board_path))
    sc->fail(sk("scenario.board"), "file " + board_path.string() + " does not exist");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(board_path, ec))
    sc->fail(sk("scenario.board"),
             board_path.string() + " is not a file (boards/<board>/board.toml)");
  s.seed = static_cast<std::uint64_t>(sc->integer(sk("scenario.seed")));
  s.tail_s = sc->number(sk("scenario.tail_s"));
  s.max_duration_s = sc->number(sk("scenario.max_duration_s"));
  s.plant.start_delay_s = sc->number(sk("scenario.start_delay_s"));
  sc->reject_unknown_keys();
  s.board = config::load_board(board_path.string());
  s.plant.disc_radius_m = s.board.controller.sigma.disc_radius_m;

  if (auto t = root.table("route")) read_route(*t, s.plant);
  if (auto t = root.table("terrain")) read_terrain(*t, s.plant);
  if (auto t = root.table("soil")) read_soil(*t, s.plant);
  if (auto t = root.table("seedlings")) read_seedlings(*t, path, s.plant);
  if (auto t = root.table("mechanism")) read_mechanism(*t, s.plant);
  if (auto t = root.table("plant")) read_plant(*t, s.plant);
  if (auto t = root.table("gnss")) read_gnss(*t, s.plant);
  if (auto t = root.table("effects")) read_effects(*t, s.plant);
  if (auto t = root.table("controller")) read_controller(*t, s);
  if (auto t = root.table("faults")) read_faults(*t, s);
  root.reject_unknown_keys();
  return s;
}

void set_operating_point(Scenario& s, double sigma, double depth_mm, double contact_area_mm2) {
  s.board.controller.sigma.sigma = sigma;
  s.board.controller.depth.target_mm = depth_mm;
  s.plant.mechanism.contact_area_mm2 = contact_area_mm2;
}

}  // namespace planter::sim
