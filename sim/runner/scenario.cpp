#include "sim/runner/scenario.h"

#include <filesystem>

#include "config/toml_section.h"
#include "sim/plant/effect_keys.h"

namespace planter::sim {

using config::ConfigError;
using config::TomlSection;

SeedlingForceModel load_seedling_force_model(const std::string& path) {
  config::TomlDocument doc(path);
  TomlSection root = doc.root();
  auto t = root.table("seedling_force");
  if (!t) throw ConfigError(path, 1, "seedling_force", "table is missing (planter-dem reduce)");
  SeedlingForceModel m;
  m.reference_diameter_mm = t->required_number("reference_diameter_mm", 3.0, 30.0, "mm");
  m.exponent = t->required_number("exponent", 0.5, 4.0);
  m.stiffness_N_per_mm_n = t->required_number("stiffness_N_per_mm_n", 1e-3, 1e5);
  m.stiffness_slope_per_mm = t->required_number("stiffness_slope_per_mm", -1e5, 1e5);
  m.peak_force_N = t->required_number("peak_force_N", 1.0, 1e4, "N");
  m.peak_force_slope_N_per_mm = t->required_number("peak_force_slope_N_per_mm", -1e4, 1e4);
  m.peak_displacement_mm = t->required_number("peak_displacement_mm", 0.05, 20.0, "mm");
  m.peak_displacement_slope = t->required_number("peak_displacement_slope", -10.0, 10.0);
  m.residual_fraction = t->required_number("residual_fraction", 0.0, 1.0);
  m.damping_N_s_per_mm = t->required_number("damping_N_s_per_mm", 0.0, 1e4);
  t->reject_unknown_keys();
  root.reject_unknown_keys();
  m.loaded = true;
  return m;
}

Scenario load_scenario(const std::string& path) {
  config::TomlDocument doc(path);
  TomlSection root = doc.root();
  Scenario s;
  s.file = path;
  auto sc = root.table("scenario");
  if (!sc) throw ConfigError(path, 1, "scenario", "table is missing (name, board, seed)");
  s.name = sc->string("name", std::filesystem::path(path).stem().string());
  const std::string board = sc->string("board", "");
  if (board.empty())
    sc->fail("board", "is required: path of a board file, relative to the scenario");
  const auto board_path = std::filesystem::path(path).parent_path() / board;
  if (!std::filesystem::exists(board_path))
    sc->fail("board", "file " + board_path.string() + " does not exist");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(board_path, ec))
    sc->fail("board", board_path.string() + " is not a file (boards/<board>/board.toml)");
  s.seed = static_cast<std::uint64_t>(sc->integer("seed", 1, 0, INT64_MAX));
  s.tail_s = sc->number("tail_s", 3.0, 0.0, 600.0, "s");
  s.max_duration_s = sc->number("max_duration_s", 3600.0, 1.0, 86400.0, "s");
  s.plant.start_delay_s = sc->number("start_delay_s", 3.0, 0.0, 600.0, "s");
  sc->reject_unknown_keys();
  s.board = config::load_board(board_path.string());
  s.plant.disc_radius_m = s.board.controller.sigma.disc_radius_m;

  PlantConfig& p = s.plant;
  if (auto r = root.table("route")) {
    p.route.distance_m = r->number("distance_m", 30.0, 0.1, 10000.0, "m");
    p.route.speed_mps = r->number("speed_mps", 0.06, 0.005, 1.0, "m/s");
    p.route.accel_mps2 = r->number("accel_mps2", 0.03, 0.001, 5.0, "m/s^2");
    p.route.speed_variation_pct = r->number("speed_variation_pct", 0.0, 0.0, 50.0, "%");
    p.route.speed_variation_period_s =
        r->number("speed_variation_period_s", 20.0, 0.5, 1000.0, "s");
    for (auto& stop : r->array_of_tables("stops")) {
      StopEvent e;
      e.at_m = stop.number("at_m", 0.0, 0.0, p.route.distance_m, "m");
      e.duration_s = stop.number("duration_s", 5.0, 0.0, 3600.0, "s");
      e.planting_off = stop.boolean("planting_off", false);
      // Off and on again needs the disc to stop and the start delay to pass within the stop.
      if (e.planting_off && e.duration_s < p.start_delay_s + 5.0)
        stop.fail("duration_s", "must be at least start_delay_s + 5 s with planting_off = true");
      stop.reject_unknown_keys();
      p.route.stops.push_back(e);
    }
    if (p.route.stops.size() > 32) r->fail("stops", "at most 32 stops");
    p.route.push_at_s = r->number("push_at_s", -1.0, -1.0, 1e6, "s");
    r->reject_unknown_keys();
  }
  if (auto t = root.table("terrain")) {
    p.terrain.roughness_mm = t->number("roughness_mm", 0.0, 0.0, 100.0, "mm");
    p.terrain.wavelength_m = t->number("wavelength_m", 0.5, 0.01, 100.0, "m");
    p.terrain.depth_share = t->number("depth_share", 0.3, 0.0, 1.0);
    t->reject_unknown_keys();
  }
  if (auto t = root.table("soil")) {
    p.soil.wheel_radius_m = t->number("wheel_radius_m", 0.15, 0.02, 1.0, "m");
    p.soil.slip_mean_pct = t->number("slip_mean_pct", 0.0, -20.0, 50.0, "%");
    p.soil.slip_variation_pct = t->number("slip_variation_pct", 0.0, 0.0, 20.0, "%");
    p.soil.slip_variation_wavelength_m =
        t->number("slip_variation_wavelength_m", 3.7, 0.1, 1000.0, "m");
    if (t->has("draft_coeff"))
      t->fail(
          "draft_coeff",
          "was c_s in a draft proportional to speed, which was wrong; the draft now has "
          "ASABE D497's form: set texture and, if measured, draft_a_N_per_cm (docs/simulator.md, "
          "\"Model assumptions\")");
    soil::OpenerDraftLaw& d = p.soil.draft;
    const std::string texture = t->string("texture", "medium");
    d.texture_factor = soil::texture_factor_of(texture);
    if (d.texture_factor < 0.0)
      t->fail("texture", "is '" + texture + "'; allowed: fine, medium, coarse (D497's F_i)");
    d.a_N_per_cm = t->number("draft_a_N_per_cm", d.a_N_per_cm, 0.0, 1e4, "N/cm");
    d.b_N_per_cm_kmh = t->number("draft_b_N_per_cm_kmh", d.b_N_per_cm_kmh, 0.0, 1e4, "N/(cm km/h)");
    d.c_N_per_cm_kmh2 =
        t->number("draft_c_N_per_cm_kmh2", d.c_N_per_cm_kmh2, 0.0, 1e4, "N/(cm (km/h)^2)");
    d.depth_exponent = t->number("draft_depth_exponent", d.depth_exponent, 1.0, 2.0);
    soil::Soil& g = p.soil.backflow;
    soil::Soil& f = p.soil.firmed;
    g.unit_weight_kN_per_m3 =
        t->number("unit_weight_kN_per_m3", g.unit_weight_kN_per_m3, 5.0, 25.0, "kN/m^3");
    g.friction_angle_deg = t->number("friction_angle_deg", g.friction_angle_deg, 10.0, 50.0, "deg");
    f.friction_angle_deg = g.friction_angle_deg;
    g.cohesion_kPa = t->number("cohesion_kPa", g.cohesion_kPa, 0.0, 100.0, "kPa");
    f.unit_weight_kN_per_m3 =
        t->number("firmed_unit_weight_kN_per_m3", f.unit_weight_kN_per_m3, 5.0, 25.0, "kN/m^3");
    f.cohesion_kPa = t->number("firmed_cohesion_kPa", f.cohesion_kPa, 0.0, 100.0, "kPa");
    t->reject_unknown_keys();
  }
  if (auto t = root.table("seedlings")) {
    SeedlingConfig& c = p.seedlings;
    c.length_min_mm = t->number("length_min_mm", c.length_min_mm, 50.0, 500.0, "mm");
    c.length_max_mm = t->number("length_max_mm", c.length_max_mm, c.length_min_mm, 500.0, "mm");
    c.diameter_min_mm = t->number("diameter_min_mm", c.diameter_min_mm, 2.0, 30.0, "mm");
    c.diameter_max_mm =
        t->number("diameter_max_mm", c.diameter_max_mm, c.diameter_min_mm, 30.0, "mm");
    if (t->has("feed_pitch_mm"))
      t->fail("feed_pitch_mm",
              "is the machine's: [planting_monitor] clamp_pitch_mm in machines/<machine>.toml "
              "(the planting monitor's target spacing comes from it too)");
    c.feed_miss_pct = t->number("feed_miss_pct", c.feed_miss_pct, 0.0, 100.0, "%");
    c.feed_double_pct =
        t->number("feed_double_pct", c.feed_double_pct, 0.0, 100.0 - c.feed_miss_pct, "%");
    // Unset: the measured peaks' (sim/seedling/measured_strength.h).
    if (t->has("strength_mean_N"))
      c.strength_mean_N = t->number("strength_mean_N", 0.0, 10.0, 1000.0, "N");
    if (t->has("strength_sd_N")) c.strength_sd_N = t->number("strength_sd_N", 0.0, 0.0, 500.0, "N");
    c.strength_diameter_exponent =
        t->number("strength_diameter_exponent", c.strength_diameter_exponent, -3.0, 3.0);
    c.strength_test_length_mm =
        t->number("strength_test_length_mm", c.strength_test_length_mm, 1.0, 200.0, "mm");
    c.tilt_noise_deg = t->number("tilt_noise_deg", c.tilt_noise_deg, 0.0, 45.0, "deg");
    c.density_kg_per_m3 =
        t->number("density_kg_per_m3", c.density_kg_per_m3, 100.0, 2000.0, "kg/m^3");
    const std::string model = t->string("force_model", "");
    if (!model.empty()) {
      const auto model_path = std::filesystem::path(path).parent_path() / model;
      if (!std::filesystem::exists(model_path))
        t->fail("force_model", "file " + model_path.string() + " does not exist");
      c.force_model = load_seedling_force_model(model_path.string());
      c.force_model_file = model;
    }
    t->reject_unknown_keys();
  }
  if (auto t = root.table("mechanism")) {
    MechanismConfig& m = p.mechanism;
    m.contact_area_mm2 = t->number("contact_area_mm2", m.contact_area_mm2, 50.0, 600.0, "mm^2");
    for (const char* old_key : {"release_angle_deg", "kinematic_gain", "optimum_sigma"})
      if (t->has(old_key))
        t->fail(old_key,
                "belonged to the tilt formula the release mechanics replaced; the release is "
                "set by release_after_lowest_deg, root_clearance_mm, residual_grip_share, "
                "root_protrusion_mm and lip_friction");
    if (t->has("root_reach_mm"))
      t->fail("root_reach_mm",
              "was typed to the paper's optimum depth and is gone: the disc rides with the "
              "opener, so the root's reach follows from the depth and root_clearance_mm");
    m.carry_angle_deg = t->number("carry_angle_deg", m.carry_angle_deg, 30.0, 300.0, "deg");
    m.release_after_lowest_deg =
        t->number("release_after_lowest_deg", m.release_after_lowest_deg, -60.0, 60.0, "deg");
    m.root_clearance_mm = t->number("root_clearance_mm", m.root_clearance_mm, 0.0, 100.0, "mm");
    m.covering_wheel_behind_mm =
        t->number("covering_wheel_behind_mm", m.covering_wheel_behind_mm, 0.0, 2000.0, "mm");
    m.handoff_speed_mismatch_mps =
        t->number("handoff_speed_mismatch_mps", m.handoff_speed_mismatch_mps, 0.0, 2.0, "m/s");
    m.protrusion_band_mm = t->number("protrusion_band_mm", m.protrusion_band_mm, 5.0, 200.0, "mm");
    m.nip_time_s = t->number("nip_time_s", m.nip_time_s, 0.01, 5.0, "s");
    m.residual_grip_share = t->number("residual_grip_share", m.residual_grip_share, 0.0, 1.0);
    m.root_protrusion_mm = t->number("root_protrusion_mm", m.root_protrusion_mm, 10.0, 200.0, "mm");
    m.lip_friction = t->number("lip_friction", m.lip_friction, 0.0, 2.0);
    m.lip_shear_modulus_MPa =
        t->number("lip_shear_modulus_MPa", m.lip_shear_modulus_MPa, 0.01, 100.0, "MPa");
    m.lip_shear_layer_mm = t->number("lip_shear_layer_mm", m.lip_shear_layer_mm, 0.5, 100.0, "mm");
    m.backflow_fill = t->number("backflow_fill", m.backflow_fill, 0.0, 1.0);
    t->reject_unknown_keys();
  }
  if (auto t = root.table("plant")) {
    DriveModelConfig& d = p.drive;
    d.disc_time_constant_s =
        t->number("disc_time_constant_s", d.disc_time_constant_s, 0.001, 5.0, "s");
    d.disc_inertia_kgm2 =
        t->number("disc_inertia_kgm2", d.disc_inertia_kgm2, 1e-4, 100.0, "kg*m^2");
    d.disc_damping_Nms = t->number("disc_damping_Nms", d.disc_damping_Nms, 0.0, 1000.0, "N*m*s");
    d.actuator_time_constant_s =
        t->number("actuator_time_constant_s", d.actuator_time_constant_s, 0.001, 5.0, "s");
    d.clamp_k_N = t->number("clamp_k_N", d.clamp_k_N, 0.1, 1e4);
    d.clamp_x0_mm = t->number("clamp_x0_mm", d.clamp_x0_mm, 0.0, 50.0, "mm");
    d.clamp_n = t->number("clamp_n", d.clamp_n, 1.0, 3.0);
    d.force_noise_N = t->number("force_noise_N", d.force_noise_N, 0.0, 50.0, "N");
    d.depth_travel_max_mm =
        t->number("depth_travel_max_mm", d.depth_travel_max_mm, 10.0, 500.0, "mm");
    t->reject_unknown_keys();
  }
  if (auto t = root.table("effects")) {
    Effects& e = p.effects;
    for (const EffectKey& k : kEffectKeys)
      e.*k.member = t->number(k.key, k.fallback, k.min, k.max, k.unit);
    if (e.clamp_relaxation_frac + e.clamp_relaxation2_frac > 0.9)
      t->fail("clamp_relaxation2_frac",
              "with clamp_relaxation_frac must stay at most 0.9 (the branches share the load)");
    t->reject_unknown_keys();
  }
  if (auto t = root.table("controller")) {
    // Operating-point overrides of the board's [control] table.
    auto& c = s.board.controller;
    c.sigma.sigma = t->number("sigma", c.sigma.sigma, 0.5, 3.0);
    c.clamp.setpoint_N = t->number("clamp_force_N", c.clamp.setpoint_N, 0.0, 200.0, "N");
    if (c.clamp.setpoint_N >= c.clamp.ceiling_N)
      t->fail("clamp_force_N", "must be below the board's clamp_ceiling_N");
    c.depth.target_mm = t->number("depth_mm", c.depth.target_mm, 40.0, 160.0, "mm");
    t->reject_unknown_keys();
  }
  if (auto t = root.table("faults")) {
    s.faults.estop_at_s = t->number("estop_at_s", -1.0, -1.0, 1e6, "s");
    s.faults.estop_release_at_s = t->number("estop_release_at_s", -1.0, -1.0, 1e6, "s");
    s.faults.silent_node = t->string("silent_node", "");
    if (!s.faults.silent_node.empty()) {
      bool known = false;
      for (std::size_t i = 0; i < kNodeCount; ++i)
        known = known || s.faults.silent_node == node_role_name(static_cast<NodeRole>(i));
      if (!known)
        t->fail("silent_node",
                "must be one of disc_drive, roller_actuator, depth_actuator, force_sensor");
    }
    s.faults.silent_at_s = t->number("silent_at_s", -1.0, -1.0, 1e6, "s");
    t->reject_unknown_keys();
  }
  root.reject_unknown_keys();
  return s;
}

void set_operating_point(Scenario& s, double sigma, double depth_mm, double contact_area_mm2) {
  s.board.controller.sigma.sigma = sigma;
  s.board.controller.depth.target_mm = depth_mm;
  s.plant.mechanism.contact_area_mm2 = contact_area_mm2;
}

}  // namespace planter::sim
