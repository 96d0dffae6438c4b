#include "sim/plant/plant.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

#include "firmware/io/signal_table.h"

namespace planter::sim {
namespace {

// A simulated drive speaks the board's units: the signal table says each object's scale.
double raw_of(const ControllerConfig& board, const SignalDecl& s, double si) {
  return si_to_bus(s.scale, board.node(s.role), si);
}
double si_of(const ControllerConfig& board, const SignalDecl& s, double raw) {
  return bus_to_si(s.scale, board.node(s.role), raw);
}
// 0x6081 profile velocity: a configuration object, in counts per second like the positions.
double profile_velocity_of(const NodeConfig& node, double raw) {
  return bus_to_si(BusScale::kPerCount, node, raw);
}
std::int16_t per_mille(double raw) {
  return static_cast<std::int16_t>(std::lround(std::clamp(raw, -32768.0, 32767.0)));
}

// The machine's own values, as the board's machine file declares them.
PlantConfig with_machine(PlantConfig config, const ControllerConfig& board) {
  config.seedlings.feed_pitch_mm = board.monitor.clamp_pitch_mm;
  return config;
}
}  // namespace

Plant::Plant(const PlantConfig& config, const ControllerConfig& board, std::uint64_t seed)
    : cfg_(with_machine(config, board)),
      board_(board),
      ground_(config.route, config.terrain),
      wheel_(config.soil.wheel_radius_m, board.encoder.counts_per_rev),
      disc_(config.drive, config.effects),
      roller_(config.drive.actuator_time_constant_s),
      depth_(config.drive.actuator_time_constant_s, 0.0, config.drive.depth_travel_max_mm),
      seedlings_(cfg_, seed ^ 0x5eed11u),
      gnss_(config.gnss, seed),
      noise_rng_(seed) {}

void Plant::step(std::int64_t t_ns, std::int64_t dt_ns, PlantDevices& dev,
                 hal::sim::SimEdgeSource& edges) {
  const double dt = static_cast<double>(dt_ns) * 1e-9;
  const double t = static_cast<double>(t_ns) * 1e-9;
  const Effects& fx = cfg_.effects;

  // Ground and soil wheel.
  const double x_before = ground_.x_m();
  ground_.step(t, dt);
  // The draft's relaxation over a step depends on the step alone: once for the plant's fixed step.
  if (dt != draft_decay_dt_s_) {
    draft_decay_dt_s_ = dt;
    draft_decay_ = soil::rest_decay(cfg_.soil.draft, dt);
  }
  draft_share_ = soil::mobilised_share_after(cfg_.soil.draft, draft_share_,
                                             ground_.x_m() - x_before, draft_decay_);
  // The draft acts at the opener's working depth in the soil (ASABE D497 takes the tool's
  // depth), which the terrain under the depth wheel and the opener's sag change, as the depth
  // sensor sees it below; the sag from the last substep's draft (1 ms), so no iteration.
  const double terrain_depth_mm = cfg_.terrain.depth_share * ground_.terrain_mm();
  const double working_depth_mm =
      depth_.position_mm() - fx.depth_sag_mm_per_kN * draft_N_ * 1e-3 + terrain_depth_mm;
  const double draft =
      soil::opener_draft_N(cfg_.soil.draft, ground_.v_mps(), working_depth_mm, draft_share_) *
      fx.changed(fx.soil_draft_change_pct, t);
  draft_N_ = draft;
  const double soil_slip_pct =
      cfg_.soil.slip_mean_pct +
      cfg_.soil.slip_variation_pct *
          std::sin(2.0 * std::numbers::pi * ground_.x_m() / cfg_.soil.slip_variation_wavelength_m);
  const double slip_pct = soil_slip_pct + fx.slip_per_kN * draft * 1e-3;
  wheel_.roll(ground_.x_m() - x_before, slip_pct * 0.01, t_ns, dt_ns, edges);
  if (dev.gnss != nullptr) gnss_.step(t_ns + dt_ns, ground_.x_m(), ground_.v_mps(), *dev.gnss);

  // Disc drive (profile velocity).
  disc_.step(
      si_of(board_, known_signal("omega_cmd"), static_cast<double>(dev.disc.target_velocity())),
      dev.disc.enabled(), dev.disc.quick_stopping(), dt);
  dev.disc.set_actual(std::llround(raw_of(board_, known_signal("disc_angle"), disc_.motor_angle())),
                      std::llround(raw_of(board_, known_signal("omega"), disc_.omega())),
                      per_mille(raw_of(board_, known_signal("disc_torque"), disc_.torque_Nm())));

  // Roller clamp actuator (profile position) and the disc lips it compresses.
  const NodeConfig& roller_node = board_.node(NodeRole::kRollerActuator);
  roller_.step(si_of(board_, known_signal("clamp_pos_cmd_mm"),
                     static_cast<double>(dev.roller.position_setpoint())),
               profile_velocity_of(roller_node, static_cast<double>(dev.roller.profile_velocity())),
               dev.roller.enabled(), dt);
  dev.roller.set_actual(
      std::llround(raw_of(board_, known_signal("clamp_pos_mm"), roller_.position_mm())), 0, 0);
  // The lips and the stem in the nip (clamp_nip.h), or the law with the stem's thickness alone.
  const double clamp_k_N = cfg_.drive.clamp_k_N * fx.changed(fx.clamp_stiffness_change_pct, t);
  const double gap_mm = roller_.position_mm() - cfg_.drive.clamp_x0_mm;
  double nip_mm = 0.0, elastic = 0.0;
  const SeedlingProcess::NipClock nip_now{t, disc_.disc_angle(), disc_.disc_omega()};
  if (const auto nip =
          seedlings_.nip_force(gap_mm, clamp_k_N, cfg_.drive.clamp_n, nip_now, elastic_N_)) {
    nip_mm = nip->added_mm;
    elastic = nip->force_N;
  } else {
    nip_mm = seedlings_.nip_thickness_mm(nip_now);
    if (const double squeezed_mm = std::max(0.0, gap_mm + nip_mm);
        squeezed_mm != clamp_compression_mm_) {
      clamp_compression_mm_ = squeezed_mm;
      clamp_power_ = std::pow(squeezed_mm, cfg_.drive.clamp_n);
    }
    elastic = clamp_k_N * clamp_power_;
  }
  elastic_N_ = elastic;
  // Viscoelastic relaxation: a Maxwell branch takes a share of the load over tau.
  if (fx.clamp_relaxation_frac > 0.0) {
    relaxation_N_ +=
        (fx.clamp_relaxation_frac * elastic - relaxation_N_) * dt / fx.clamp_relaxation_tau_s;
  }
  // A second branch: a generalized Maxwell (Prony) series of two terms (Findley, "Creep and
  // Relaxation of Nonlinear Viscoelastic Materials", ch. 5).
  if (fx.clamp_relaxation2_frac > 0.0) {
    relaxation2_N_ +=
        (fx.clamp_relaxation2_frac * elastic - relaxation2_N_) * dt / fx.clamp_relaxation2_tau_s;
  }
  const double clamp_force = std::max(0.0, elastic - relaxation_N_ - relaxation2_N_);
  std::normal_distribution<double> noise(0.0, 1.0);
  const double vibration =
      fx.vibration_hz > 0.0 ? std::sin(2.0 * std::numbers::pi * fx.vibration_hz * t) : 0.0;
  const double measured = (clamp_force + fixture_load_N_) * (1.0 + 0.01 * fx.force_gain_pct) +
                          cfg_.drive.force_noise_N * noise(noise_rng_) + fx.force_offset_N +
                          fx.force_drift_N_per_min * t / 60.0 + fx.vibration_force_N * vibration;
  dev.force.set_force_N(measured);

  // Furrow opener depth actuator (profile position) against soil draft.
  const NodeConfig& depth_node = board_.node(NodeRole::kDepthActuator);
  depth_.step(si_of(board_, known_signal("depth_cmd_mm"),
                    static_cast<double>(dev.depth.position_setpoint())),
              profile_velocity_of(depth_node, static_cast<double>(dev.depth.profile_velocity())),
              dev.depth.enabled(), dt);
  // The depth-limiting wheel follows the surface, but only partly over micro-terrain.
  const double depth_true =
      depth_.position_mm() - fx.depth_sag_mm_per_kN * draft * 1e-3 + terrain_depth_mm;
  dev.depth.set_actual(std::llround(raw_of(board_, known_signal("depth_mm"), depth_true)), 0,
                       per_mille(raw_of(board_, known_signal("depth_force"), draft)));

  // Seedlings.
  const ReleaseConditions now{t,          ground_.x_m(), ground_.v_mps(),     disc_.disc_omega(),
                              depth_true, clamp_force,   ground_.terrain_mm()};
  seedlings_.step(disc_.disc_angle(), clamp_force, now, fx.vibration_tilt_deg);
  if (board_.monitor.sensor_fitted) photo_eye(t_ns + dt_ns, edges);

  truth_.x_m = ground_.x_m();
  truth_.v_mps = ground_.v_mps();
  truth_.slip = slip_pct * 0.01;
  truth_.disc_omega_radps = disc_.disc_omega();
  truth_.sigma =
      ground_.v_mps() > 1e-4 ? cfg_.disc_radius_m * disc_.disc_omega() / ground_.v_mps() : 0.0;
  truth_.clamp_force_N = clamp_force;
  truth_.roller_mm = roller_.position_mm();
  truth_.depth_mm = depth_true;
  truth_.draft_N = draft;
  truth_.terrain_mm = ground_.terrain_mm();
  // About the mean: the soil wheel's calibration (an effective radius measured by pushing
  // the machine over a known distance on this soil) already holds the mean slip.
  truth_.known_slip = (soil_slip_pct - cfg_.soil.slip_mean_pct) * 0.01;
  truth_.known_terrain_depth_mm = terrain_depth_mm;
  truth_.known_nip_mm = nip_mm;
  truth_.seedling_in_nip = seedlings_.seedling_in_nip(t);
}

void Plant::photo_eye(std::int64_t end_ns, hal::sim::SimEdgeSource& edges) {
  // Stamped at the step's end, after the step's encoder edges, so the queue stays in time
  // order and the wheel's count at the break is the one at the seedling's release.
  if (beam_broken_ && end_ns >= beam_clear_ns_) {
    edges.push({hal::edge_line::kSeedlingSensor, false, end_ns});
    beam_broken_ = false;
  }
  const std::vector<Seedling>& all = seedlings_.seedlings();
  while (photo_eye_seen_ < seedlings_.released()) {
    const Seedling& s = all[photo_eye_seen_++];
    if (!s.planted) continue;  // it fell from the clamp in the carry: nothing passes the eye
    if (beam_broken_) edges.push({hal::edge_line::kSeedlingSensor, false, end_ns});
    edges.push({hal::edge_line::kSeedlingSensor, true, end_ns});
    // The beam stays broken while the disc carries the stem's diameter past it.
    const double rim_mps = std::max(1e-3, std::abs(disc_.disc_omega()) * cfg_.disc_radius_m);
    beam_broken_ = true;
    beam_clear_ns_ = end_ns + static_cast<std::int64_t>(s.diameter_mm * 1e-3 / rim_mps * 1e9);
  }
}

}  // namespace planter::sim
