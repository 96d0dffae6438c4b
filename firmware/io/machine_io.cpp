#include "firmware/io/machine_io.h"

#include <cmath>

#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/nmt.h"

namespace planter {

using canopen::cia402::State;

MachineIo::MachineIo(const MachineIoConfig& config, hal::ControllerHal& hal)
    : cfg_(config),
      hal_(hal),
      links_{NodeLink(config.nodes[0], config.can), NodeLink(config.nodes[1], config.can),
             NodeLink(config.nodes[2], config.can), NodeLink(config.nodes[3], config.can)},
      decoder_(config.encoder.glitch_filter_ns),
      ground_speed_(metres_per_count(config.encoder), config.encoder.speed_window_ns) {
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    const SignalDecl& s = kSignals[i];
    slots_[i] = s.on_bus() ? link(s.role).slot(s.index, s.sub) : -1;
  }
}

const MachineState& MachineIo::read(std::int64_t now_ns) {
  read_bus(now_ns);
  read_encoder(now_ns);
  read_process_values();
  state_.estop = hal_.estop.asserted();
  if (hal_.gnss != nullptr) {
    state_.gnss_fitted = true;
    state_.gnss_connected = hal_.gnss->connected();
    if (hal_.gnss->latest(state_.gnss)) state_.v_gnss_mps = state_.gnss.speed_mps;
    const bool placed = state_.gnss_connected && hal::has_position(state_.gnss) &&
                        now_ns - state_.gnss.valid_ns <= MachineState::kGnssPlaceMaxAgeNs;
    state_.lat_deg = placed ? state_.gnss.lat_deg : 0.0;
    state_.lon_deg = placed ? state_.gnss.lon_deg : 0.0;
  }
  const hal::CanBusCounters bus = hal_.can.counters();
  state_.link_up = bus.link_up;
  state_.link_downs = bus.link_downs;
  state_.link_faults = check_links(now_ns) | (bus.bus_off ? fault::kBusOff : 0u);
  bool ready = state_.nodes_started;
  for (const NodeLink& l : links_) {
    ready = ready && l.heartbeat().state() == canopen::NmtState::kOperational;
    if (l.config().profile == 402) ready = ready && l.drive_state() == State::kOperationEnabled;
  }
  state_.nodes_ready = ready;
  return state_;
}

void MachineIo::read_bus(std::int64_t now_ns) {
  hal::CanFrame f;
  while (hal_.can.receive(f)) {
    if (!f.is_standard_data()) continue;  // error frames are counted by the bus itself
    // Heartbeats, TPDOs and SDO answers are timed from the frame's arrival where the bus
    // knows it, not from this tick (a late tick must not make a node look late).
    const std::int64_t at_ns = f.rx_time_ns >= 0 && f.rx_time_ns <= now_ns ? f.rx_time_ns : now_ns;
    bool claimed = false;
    for (NodeLink& l : links_) {
      if (l.on_frame(f, at_ns, hal_.can)) {
        claimed = true;
        break;
      }
    }
    if (!claimed && f.cob_id() != canopen::kSyncCobId && f.cob_id() != canopen::kNmtCobId) {
      ++state_.unknown_frames;  // unknown IDs: counted and ignored
    }
  }
}

void MachineIo::read_encoder(std::int64_t now_ns) {
  hal::GpioEdge e;
  state_.seedlings_this_tick = 0;
  const double m_per_count = metres_per_count(cfg_.encoder);
  while (hal_.edges.next_edge(e)) {
    if (e.line != hal::edge_line::kSeedlingSensor) {
      decoder_.on_edge(e);
      continue;
    }
    // The edges come in time order, so the decoder's count is the wheel's at the beam break.
    // A break within the filter time of the last one is the same seedling's flicker.
    if (!e.rising || e.time_ns - last_seedling_ns_ < cfg_.seedling_filter_ns) continue;
    last_seedling_ns_ = e.time_ns;
    if (state_.seedlings_this_tick < MachineState::kMaxSeedlingsPerTick) {
      state_.seedling_at_m[state_.seedlings_this_tick++] =
          static_cast<double>(decoder_.count()) * m_per_count;
    } else {
      ++state_.seedlings_dropped;
    }
  }
  ground_speed_.update(decoder_.count(), decoder_.last_count_time_ns(), now_ns);
  state_.wheel_counts = decoder_.count();
  state_.distance_m = ground_speed_.distance_m();
  state_.v_wheel_mps = ground_speed_.speed_mps();
  state_.encoder_invalid = decoder_.invalid_transitions();
}

void MachineIo::read_process_values() {
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    const SignalDecl& s = kSignals[i];
    if (s.source != SignalSource::kNode) continue;
    const NodeLink& l = link(s.role);
    state_.*s.measured = bus_to_si(s.scale, l.config(), static_cast<double>(l.value(slots_[i])));
  }
}

// Faults the links show by themselves: a failed or overlong boot while commissioning; after
// it, lost heartbeats, unexpected boot-ups, emergencies, stale TPDOs and drive faults.
std::uint32_t MachineIo::check_links(std::int64_t now_ns) const {
  std::uint32_t faults = 0;
  if (commissioning_) {
    bool failed = commissioning_started_ && now_ns - commissioning_start_ns_ > cfg_.boot_timeout_ns;
    for (const NodeLink& l : links_)
      failed = failed || l.boot_state() == NodeLink::BootState::kFailed;
    return failed ? fault::kBootFailed : 0u;
  }
  if (!state_.nodes_started) return faults;
  for (std::size_t i = 0; i < kNodeCount; ++i) {
    const NodeLink& l = links_[i];
    if (l.heartbeat().timed_out(now_ns)) faults |= fault::kHeartbeatLost;
    if (l.heartbeat().boot_ups() != boot_ups_seen_[i]) faults |= fault::kUnexpectedBootUp;
    if (l.last_emcy_code() != 0) faults |= fault::kEmergency;
    if (now_ns - l.last_tpdo_ns() > cfg_.pdo_stale_ns) faults |= fault::kPdoStale;
    if (l.config().profile == 402 && l.drive_state() == State::kFault) faults |= fault::kDriveFault;
  }
  return faults;
}

void MachineIo::write(std::int64_t now_ns, const MachineCommand& command) {
  commissioning_ = command.commissioning;
  if (command.commissioning) {
    step_commissioning(now_ns);
  } else {
    commissioning_started_ = false;
  }
  hal_.status_lamp.set(command.status_lamp);
  if (!state_.nodes_started) return;  // PDOs are not configured before the nodes are started

  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    const SignalDecl& s = kSignals[i];
    if (s.commanded == nullptr || !s.on_bus()) continue;
    NodeLink& l = link(s.role);
    const std::int64_t counts = std::llround(si_to_bus(s.scale, l.config(), command.*s.commanded));
    if (s.index == canopen::cia402::kTargetPosition) {
      l.set_position_target(counts);  // taken with the next new-set-point edge
    } else {
      l.set_value(slots_[i], counts);
    }
  }
  const State wanted = command.drives_enabled ? State::kOperationEnabled : State::kQuickStopActive;
  for (NodeLink& l : links_) l.drive_towards(wanted);
  for (NodeLink& l : links_) l.send_rpdos(hal_.can);
  send_sync();
}

void MachineIo::step_commissioning(std::int64_t now_ns) {
  if (!commissioning_started_) {
    // Reset every node's communication so each boots into a known configuration.
    hal_.can.send(canopen::nmt_frame(canopen::NmtCommand::kResetCommunication, 0));
    commissioning_started_ = true;
    commissioning_start_ns_ = now_ns;
    state_.nodes_started = false;
    for (std::size_t i = 0; i < kNodeCount; ++i) {
      links_[i].heartbeat().disarm();
      links_[i].clear_emcy();
      boot_ups_seen_[i] = links_[i].heartbeat().boot_ups();
    }
    for (NodeLink& l : links_) l.start_boot(now_ns + 1, hal_.can);  // after the reset frame
    return;
  }
  bool all_configured = true;
  for (NodeLink& l : links_) {
    l.step_boot(now_ns, hal_.can);
    all_configured = all_configured && l.boot_state() == NodeLink::BootState::kConfigured;
  }
  if (all_configured && !state_.nodes_started) {
    for (std::size_t i = 0; i < kNodeCount; ++i) {
      NodeLink& l = links_[i];
      hal_.can.send(canopen::nmt_frame(canopen::NmtCommand::kStart, l.config().node_id));
      l.heartbeat().arm(now_ns);
      boot_ups_seen_[i] = l.heartbeat().boot_ups();
    }
    state_.nodes_started = true;
  }
}

void MachineIo::send_sync() {
  hal::CanFrame sync{};
  sync.id = canopen::kSyncCobId;
  sync.dlc = 0;
  hal_.can.send(sync);
}

}  // namespace planter
