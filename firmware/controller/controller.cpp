#include "firmware/controller/controller.h"

#include <cmath>

#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/nmt.h"

namespace planter {

using canopen::cia402::State;

namespace {
constexpr double kTwoPi = 6.283185307179586;

double metres_per_count(const EncoderConfig& e) {
  return kTwoPi * e.wheel_radius_m / static_cast<double>(e.counts_per_rev);
}
}  // namespace

Controller::Controller(const ControllerConfig& config, hal::ControllerHal& hal)
    : cfg_(config),
      hal_(hal),
      links_{NodeLink(config.nodes[0], config.can), NodeLink(config.nodes[1], config.can),
             NodeLink(config.nodes[2], config.can), NodeLink(config.nodes[3], config.can)},
      decoder_(config.encoder.glitch_filter_ns),
      ground_speed_(metres_per_count(config.encoder), config.encoder.speed_window_ns),
      sigma_loop_(config.sigma),
      clamp_loop_(config.clamp),
      depth_loop_(config.depth) {
  NodeLink& disc = link(NodeRole::kDiscDrive);
  disc_velocity_slot_ = disc.slot(canopen::cia402::kVelocityActual);
  disc_position_slot_ = disc.slot(canopen::cia402::kPositionActual);
  disc_torque_slot_ = disc.slot(canopen::cia402::kTorqueActual);
  disc_target_slot_ = disc.slot(canopen::cia402::kTargetVelocity);
  roller_position_slot_ = link(NodeRole::kRollerActuator).slot(canopen::cia402::kPositionActual);
  depth_position_slot_ = link(NodeRole::kDepthActuator).slot(canopen::cia402::kPositionActual);
  depth_torque_slot_ = link(NodeRole::kDepthActuator).slot(canopen::cia402::kTorqueActual);
  force_slot_ = link(NodeRole::kForceSensor).slot(0x7130, 1);
}

void Controller::tick(std::int64_t now_ns, std::int64_t dt_ns) {
  read_bus(now_ns);
  read_encoder(now_ns);
  read_process_values();
  mark(hal::TickPhase::kReceive);

  SupervisorInputs in;
  in.estop = hal_.estop.asserted();
  in.faults = check_faults(now_ns, dt_ns);
  bool ready = nodes_started_;
  for (const NodeLink& l : links_) {
    ready = ready && l.heartbeat().state() == canopen::NmtState::kOperational;
    if (l.config().profile == 402) ready = ready && l.drive_state() == State::kOperationEnabled;
  }
  in.nodes_ready = ready;
  in.disc_stopped = std::abs(telemetry_.omega_radps) < cfg_.supervisor.stopped_omega_radps;
  in.run_requested = run_requested_;
  in.stop_requested = stop_requested_;
  in.reset_requested = reset_requested_;
  run_requested_ = stop_requested_ = reset_requested_ = false;

  const SupervisorState state = supervisor_.update(in);
  if (state != previous_state_) {
    if (state == SupervisorState::kCommissioning) commissioning_started_ = false;
    if (state == SupervisorState::kRunning) {
      sigma_loop_.engage(telemetry_.distance_m, telemetry_.disc_angle_rad);
      clamp_loop_.reset();
      depth_loop_.reset(telemetry_.depth_mm);
    }
    previous_state_ = state;
  }
  if (state == SupervisorState::kCommissioning) run_commissioning(now_ns);
  mark(hal::TickPhase::kControl);

  write_outputs(static_cast<double>(dt_ns) * 1e-9);
  send_sync();
  mark(hal::TickPhase::kTransmit);

  telemetry_.time_ns = now_ns;
  telemetry_.state = state;
  telemetry_.faults = supervisor_.latched_faults() | in.faults;
  hal_.status_lamp.set(state == SupervisorState::kRunning);
}

void Controller::read_bus(std::int64_t now_ns) {
  hal::CanFrame f;
  while (hal_.can.receive(f)) {
    if (!f.is_standard_data()) continue;  // error frames are counted by the bus itself
    bool claimed = false;
    for (NodeLink& l : links_) {
      if (l.on_frame(f, now_ns, hal_.can)) {
        claimed = true;
        break;
      }
    }
    if (!claimed && f.cob_id() != canopen::kSyncCobId && f.cob_id() != canopen::kNmtCobId) {
      ++telemetry_.unknown_frames;  // unknown IDs: counted and ignored
    }
  }
}

void Controller::read_encoder(std::int64_t now_ns) {
  hal::GpioEdge e;
  while (hal_.encoder.next_edge(e)) decoder_.on_edge(e);
  ground_speed_.update(decoder_.count(), decoder_.last_count_time_ns(), now_ns);
  telemetry_.wheel_counts = decoder_.count();
  telemetry_.distance_m = ground_speed_.distance_m();
  telemetry_.v_wheel_mps = ground_speed_.speed_mps();
  telemetry_.encoder_invalid = decoder_.invalid_transitions();
}

void Controller::read_process_values() {
  const NodeLink& disc = link(NodeRole::kDiscDrive);
  const double disc_counts = disc.config().counts_per_unit;
  telemetry_.omega_radps = static_cast<double>(disc.value(disc_velocity_slot_)) / disc_counts;
  telemetry_.disc_angle_rad = static_cast<double>(disc.value(disc_position_slot_)) / disc_counts;
  telemetry_.disc_torque_Nm =
      static_cast<double>(disc.value(disc_torque_slot_)) * 1e-3 * disc.config().rated_torque;
  const NodeLink& roller = link(NodeRole::kRollerActuator);
  telemetry_.clamp_pos_mm =
      static_cast<double>(roller.value(roller_position_slot_)) / roller.config().counts_per_unit;
  const NodeLink& depth = link(NodeRole::kDepthActuator);
  telemetry_.depth_mm =
      static_cast<double>(depth.value(depth_position_slot_)) / depth.config().counts_per_unit;
  telemetry_.depth_force_N =
      static_cast<double>(depth.value(depth_torque_slot_)) * 1e-3 * depth.config().rated_torque;
  const NodeLink& force = link(NodeRole::kForceSensor);
  telemetry_.clamp_force_N =
      (static_cast<double>(force.value(force_slot_)) - force.config().zero_counts) /
      force.config().counts_per_unit;
  telemetry_.sigma = sigma_loop_.sigma_seen(telemetry_.omega_radps, telemetry_.v_wheel_mps);
}

std::uint32_t Controller::check_faults(std::int64_t now_ns, std::int64_t dt_ns) {
  std::uint32_t faults = 0;
  if (dt_ns > cfg_.supervisor.overrun_threshold_ns) {
    ++telemetry_.overruns;
    if (++consecutive_overruns_ >= cfg_.supervisor.overruns_to_fault) faults |= fault::kOverrun;
  } else {
    consecutive_overruns_ = 0;
  }
  if (hal_.can.counters().bus_off) faults |= fault::kBusOff;
  if (supervisor_.state() == SupervisorState::kCommissioning) {
    bool failed = commissioning_started_ &&
                  now_ns - commissioning_start_ns_ > cfg_.supervisor.boot_timeout_ns;
    for (const NodeLink& l : links_)
      failed = failed || l.boot_state() == NodeLink::BootState::kFailed;
    if (failed) faults |= fault::kBootFailed;
    return faults;
  }
  if (!nodes_started_) return faults;
  for (std::size_t i = 0; i < kNodeCount; ++i) {
    const NodeLink& l = links_[i];
    if (l.heartbeat().timed_out(now_ns)) faults |= fault::kHeartbeatLost;
    if (l.heartbeat().boot_ups() != boot_ups_seen_[i]) faults |= fault::kUnexpectedBootUp;
    if (l.last_emcy_code() != 0) faults |= fault::kEmergency;
    if (now_ns - l.last_tpdo_ns() > cfg_.supervisor.pdo_stale_ns) faults |= fault::kPdoStale;
    if (l.config().profile == 402 && l.drive_state() == State::kFault) faults |= fault::kDriveFault;
  }
  const SupervisorConfig& s = cfg_.supervisor;
  if (telemetry_.clamp_force_N < s.force_plausible_min_N ||
      telemetry_.clamp_force_N > s.force_plausible_max_N ||
      std::abs(telemetry_.v_wheel_mps) > s.ground_speed_plausible_max_mps) {
    faults |= fault::kSensorImplausible;
  }
  const double omega_expected =
      cfg_.sigma.sigma * std::abs(telemetry_.v_wheel_mps) / cfg_.sigma.disc_radius_m;
  if (std::abs(telemetry_.omega_radps) > omega_expected + s.disc_plausible_margin_radps) {
    disc_implausible_ns_ += dt_ns;
  } else {
    disc_implausible_ns_ = 0;
  }
  if (disc_implausible_ns_ > s.disc_implausible_ns) faults |= fault::kSensorImplausible;
  return faults;
}

void Controller::run_commissioning(std::int64_t now_ns) {
  if (!commissioning_started_) {
    // Reset every node's communication so each boots into a known configuration.
    send_nmt(canopen::NmtCommand::kResetCommunication, 0);
    commissioning_started_ = true;
    commissioning_start_ns_ = now_ns;
    nodes_started_ = false;
    for (std::size_t i = 0; i < kNodeCount; ++i) {
      links_[i].heartbeat().disarm();
      links_[i].clear_emcy();
      boot_ups_seen_[i] = links_[i].heartbeat().boot_ups();
    }
    for (NodeLink& l : links_) l.start_boot(now_ns + 1, hal_.can);  // after the reset frame
    return;
  }
  bool all_configured = true;
  for (std::size_t i = 0; i < kNodeCount; ++i) {
    NodeLink& l = links_[i];
    l.step_boot(now_ns, hal_.can);
    all_configured = all_configured && l.boot_state() == NodeLink::BootState::kConfigured;
  }
  if (all_configured && !nodes_started_) {
    for (std::size_t i = 0; i < kNodeCount; ++i) {
      NodeLink& l = links_[i];
      send_nmt(canopen::NmtCommand::kStart, l.config().node_id);
      l.heartbeat().arm(now_ns);
      boot_ups_seen_[i] = l.heartbeat().boot_ups();
    }
    nodes_started_ = true;
  }
}

void Controller::write_outputs(double dt_s) {
  const SupervisorState state = supervisor_.state();
  const bool operating = state == SupervisorState::kReady || state == SupervisorState::kRunning ||
                         state == SupervisorState::kStopping ||
                         state == SupervisorState::kCommissioning;
  const State wanted = operating ? State::kOperationEnabled : State::kQuickStopActive;

  double omega_cmd = 0.0;
  double clamp_pos_cmd = cfg_.clamp.release_position_mm;
  double depth_cmd = cfg_.depth.raised_mm;
  if (state == SupervisorState::kRunning) {
    omega_cmd = sigma_loop_.update(telemetry_.distance_m, telemetry_.v_wheel_mps,
                                   telemetry_.disc_angle_rad);
    clamp_pos_cmd = clamp_loop_.update(telemetry_.clamp_force_N, dt_s, true);
    depth_cmd = depth_loop_.update(telemetry_.depth_mm, dt_s, true);
  } else if (state == SupervisorState::kStopping) {
    clamp_pos_cmd = clamp_loop_.update(telemetry_.clamp_force_N, dt_s, true);
    depth_cmd = depth_loop_.update(telemetry_.depth_mm, dt_s, true);
  } else if (state == SupervisorState::kFault || state == SupervisorState::kEStop) {
    // Safe outputs: every drive quick-stops where it is; commands are held at the measured values.
    clamp_pos_cmd = telemetry_.clamp_pos_mm;
    depth_cmd = telemetry_.depth_mm;
  } else {
    depth_cmd = depth_loop_.update(telemetry_.depth_mm, dt_s, false);
  }
  telemetry_.omega_cmd_radps = omega_cmd;
  telemetry_.clamp_pos_cmd_mm = clamp_pos_cmd;
  telemetry_.clamp_force_cmd_N =
      state == SupervisorState::kRunning || state == SupervisorState::kStopping
          ? clamp_loop_.setpoint_N()
          : 0.0;
  telemetry_.depth_cmd_mm = depth_cmd;

  if (!nodes_started_) return;  // PDOs are not configured before the nodes are started
  NodeLink& disc = link(NodeRole::kDiscDrive);
  disc.set_value(disc_target_slot_, std::llround(omega_cmd * disc.config().counts_per_unit));
  disc.drive_towards(wanted);
  NodeLink& roller = link(NodeRole::kRollerActuator);
  roller.set_position_target(std::llround(clamp_pos_cmd * roller.config().counts_per_unit));
  roller.drive_towards(wanted);
  NodeLink& depth = link(NodeRole::kDepthActuator);
  depth.set_position_target(std::llround(depth_cmd * depth.config().counts_per_unit));
  depth.drive_towards(wanted);
  for (NodeLink& l : links_) l.send_rpdos(hal_.can);
}

void Controller::send_nmt(canopen::NmtCommand command, std::uint8_t node_id) {
  hal_.can.send(canopen::nmt_frame(command, node_id));  // node 0 = every node
}

void Controller::send_sync() {
  if (!nodes_started_) return;
  hal::CanFrame sync{};
  sync.id = canopen::kSyncCobId;
  sync.dlc = 0;
  hal_.can.send(sync);
}

}  // namespace planter
