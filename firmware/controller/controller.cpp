#include "firmware/controller/controller.h"

#include <cmath>

#include "firmware/controller/setpoint_rules.h"

namespace planter {

Controller::Controller(const ControllerConfig& config)
    : cfg_(config),
      ground_(config.ground),
      sigma_loop_(config.sigma),
      clamp_loop_(config.clamp),
      depth_loop_(config.depth),
      link_recovery_(config.link_recovery),
      monitor_(config.monitor),
      alarms_(config.alarms),
      load_cell_zero_(config.load_cell_zero) {}

const MachineCommand& Controller::update(const MachineState& in, std::int64_t now_ns,
                                         std::int64_t dt_ns) {
  if (link_recovery_.update(
          {now_ns, in.link_up, in.link_downs, supervisor_.state(), supervisor_.latched_faults()})) {
    reset_requested_ = true;
  }
  ground_.update(in, now_ns);
  command_.sigma = sigma_loop_.sigma_seen(in.omega_radps, ground_.speed_mps());
  command_.ground_speed_mps = ground_.speed_mps();
  command_.slip_est = ground_.slip();
  command_.gnss_use = ground_.use();

  SupervisorInputs sv;
  sv.estop = in.estop;
  estop_held_ = in.estop;
  sv.faults = check_faults(in, dt_ns);
  sv.nodes_ready = in.nodes_ready;
  sv.disc_stopped = std::abs(in.omega_radps) < cfg_.supervisor.stopped_omega_radps;
  sv.run_requested = run_requested_;
  sv.stop_requested = stop_requested_;
  sv.reset_requested = reset_requested_;
  run_requested_ = stop_requested_ = reset_requested_ = false;

  const SupervisorState state = supervisor_.update(sv);
  if (state != previous_state_) {
    if (state == SupervisorState::kRunning) {
      sigma_loop_.engage(ground_.distance_m(), in.disc_angle_rad);
      clamp_loop_.reset();
      depth_loop_.reset(in.depth_mm);
      alarms_.reset();
    }
    previous_state_ = state;
  }
  // The lips are held open for the load cell's zero at each start (load_cell_zero.h).
  running_for_ns_ = state == SupervisorState::kRunning ? running_for_ns_ + dt_ns : 0;
  zeroing_ = state == SupervisorState::kRunning &&
             static_cast<double>(running_for_ns_) * 1e-9 < cfg_.load_cell_zero.zero_s;
  const bool lips_open =
      (state == SupervisorState::kReady || zeroing_) &&
      in.clamp_pos_mm < cfg_.clamp.model_x0_mm - cfg_.load_cell_zero.clear_of_contact_mm;
  load_cell_zero_.update(in.clamp_force_N, lips_open);
  decide_outputs(in, state, static_cast<double>(dt_ns) * 1e-9);
  // The planting monitor measures spacings on the fused ground, as the sigma loop holds them.
  MachineState on_ground = in;
  on_ground.distance_m = ground_.distance_m();
  for (std::uint32_t i = 0; i < MachineState::kMaxSeedlingsPerTick; ++i)
    on_ground.seedling_at_m[i] = ground_.ground_m(in.seedling_at_m[i]);
  monitor_.update(on_ground,
                  state == SupervisorState::kRunning || state == SupervisorState::kStopping);
  LoopAlarmInputs alarm_in;
  alarm_in.running = state == SupervisorState::kRunning;
  alarm_in.dt_s = static_cast<double>(dt_ns) * 1e-9;
  alarm_in.disc_angle_rad = in.disc_angle_rad;
  alarm_in.clamp_setpoint_N = clamp_loop_.setpoint_N();
  alarm_in.sigma = sigma_loop_.status();
  alarm_in.clamp = clamp_loop_.status();
  alarm_in.depth = depth_loop_.status();
  alarm_in.empty_belt = monitor_.figures().empty_belt;
  alarm_in.wheel_alone = ground_.wheel_alone();
  warnings_ = alarms_.update(alarm_in);
  faults_seen_ = supervisor_.latched_faults() | sv.faults;
  return command_;
}

CommandOutcome Controller::command(const OperatorCommand& c) {
  const SupervisorState s = supervisor_.state();
  const bool estop = estop_held_ || s == SupervisorState::kEStop;
  switch (c.kind) {
    case CommandKind::kStop:
      request_stop();  // stopping is never unsafe; in e-stop or fault the drives are off already
      return CommandOutcome::kAccepted;
    case CommandKind::kFaultReset:
      if (estop_held_) return CommandOutcome::kRefusedEStop;
      request_fault_reset();
      return CommandOutcome::kAccepted;
    case CommandKind::kRun:
      if (estop) return CommandOutcome::kRefusedEStop;
      if (s == SupervisorState::kFault) return CommandOutcome::kRefusedFault;
      if (!run_gate_open_) return CommandOutcome::kRefusedGate;
      if (s != SupervisorState::kReady && s != SupervisorState::kRunning)
        return CommandOutcome::kRefusedNotReady;
      request_run();
      return CommandOutcome::kAccepted;
    case CommandKind::kSetDepth:
    case CommandKind::kSetClampForce:
      // Nothing changes while the e-stop or a fault holds.
      if (estop) return CommandOutcome::kRefusedEStop;
      if (s == SupervisorState::kFault) return CommandOutcome::kRefusedFault;
      if (c.kind == CommandKind::kSetDepth) {
        if (!depth_range_mm(cfg_).allows(c.value)) return CommandOutcome::kOutOfRange;
        depth_loop_.set_target_mm(c.value);
      } else {
        if (!clamp_force_range_N(cfg_).allows(c.value)) return CommandOutcome::kOutOfRange;
        clamp_loop_.set_target_N(c.value);
      }
      return CommandOutcome::kAccepted;
  }
  return CommandOutcome::kOutOfRange;
}

std::uint32_t Controller::check_faults(const MachineState& in, std::int64_t dt_ns) {
  std::uint32_t faults = in.link_faults;
  if (dt_ns > cfg_.supervisor.overrun_threshold_ns) {
    ++overruns_;
    if (++consecutive_overruns_ >= cfg_.supervisor.overruns_to_fault) faults |= fault::kOverrun;
  } else {
    consecutive_overruns_ = 0;
  }
  // Plausibility needs running nodes: while they boot their values mean nothing.
  if (supervisor_.state() == SupervisorState::kCommissioning || !in.nodes_started) return faults;
  const SupervisorConfig& s = cfg_.supervisor;
  if (in.clamp_force_N < s.force_plausible_min_N || in.clamp_force_N > s.force_plausible_max_N ||
      std::abs(in.v_wheel_mps) > s.ground_speed_plausible_max_mps) {
    faults |= fault::kSensorImplausible;
  }
  const double omega_expected =
      cfg_.sigma.sigma * std::abs(in.v_wheel_mps) / cfg_.sigma.disc_radius_m;
  if (std::abs(in.omega_radps) > omega_expected + s.disc_plausible_margin_radps) {
    disc_implausible_ns_ += dt_ns;
  } else {
    disc_implausible_ns_ = 0;
  }
  if (disc_implausible_ns_ > s.disc_implausible_ns) faults |= fault::kSensorImplausible;
  return faults;
}

void Controller::decide_outputs(const MachineState& in, SupervisorState state, double dt_s) {
  const bool operating = state == SupervisorState::kReady || state == SupervisorState::kRunning ||
                         state == SupervisorState::kStopping ||
                         state == SupervisorState::kCommissioning;
  double omega_cmd = 0.0;
  double clamp_pos_cmd = cfg_.clamp.release_position_mm;
  double depth_cmd = cfg_.depth.raised_mm;
  const double force_N = load_cell_zero_.corrected_N(in.clamp_force_N);
  const double rim_mm_per_s = std::abs(in.omega_radps) * cfg_.sigma.disc_radius_m * 1e3;
  clamp_loop_.set_stem_reading_trusted((warnings_ & warning::kLoadCellDisagrees) == 0);
  if (state == SupervisorState::kRunning) {
    omega_cmd =
        sigma_loop_.update(ground_.distance_m(), ground_.speed_mps(), in.disc_angle_rad, dt_s);
    clamp_pos_cmd = clamp_loop_.update(force_N, in.clamp_pos_mm, rim_mm_per_s, dt_s, !zeroing_);
    depth_cmd = depth_loop_.update(in.depth_mm, dt_s, true);
  } else if (state == SupervisorState::kStopping) {
    clamp_pos_cmd = clamp_loop_.update(force_N, in.clamp_pos_mm, rim_mm_per_s, dt_s, !zeroing_);
    depth_cmd = depth_loop_.update(in.depth_mm, dt_s, true);
  } else if (state == SupervisorState::kFault || state == SupervisorState::kEStop) {
    // Safe outputs: every drive quick-stops where it is; commands are held at the measured values.
    clamp_pos_cmd = in.clamp_pos_mm;
    depth_cmd = in.depth_mm;
  } else {
    depth_cmd = depth_loop_.update(in.depth_mm, dt_s, false);
  }
  command_.omega_cmd_radps = omega_cmd;
  command_.clamp_pos_cmd_mm = clamp_pos_cmd;
  command_.clamp_force_cmd_N =
      state == SupervisorState::kRunning || state == SupervisorState::kStopping
          ? clamp_loop_.setpoint_N()
          : 0.0;
  command_.depth_cmd_mm = depth_cmd;
  command_.depth_target_mm = depth_loop_.target_mm();
  command_.clamp_force_target_N = clamp_loop_.target_N();
  command_.clamp_force_aim_N = clamp_loop_.aim_N();
  command_.drives_enabled = operating;
  command_.commissioning = state == SupervisorState::kCommissioning;
  command_.status_lamp = state == SupervisorState::kRunning;
}

}  // namespace planter
