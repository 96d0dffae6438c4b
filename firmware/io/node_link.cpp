#include "firmware/io/node_link.h"

#include <algorithm>
#include <cstdint>

#include "firmware/canopen/cob_id.h"

namespace planter {

using canopen::cia402::State;

NodeLink::NodeLink(const NodeConfig& config, const CanConfig& can)
    : cfg_(config),
      heartbeat_ms_(can.heartbeat_producer_ms),
      sdo_(config.node_id, can.sdo_timeout_ns),
      heartbeat_(static_cast<std::int64_t>(can.heartbeat_producer_ms *
                                           can.heartbeat_consumer_factor * 1e6)) {
  for (std::size_t k = 0; k < 4; ++k) {
    tpdo_slots_[k].fill(-1);
    rpdo_slots_[k].fill(-1);
    for (std::uint8_t i = 0; i < cfg_.tpdo[k].count; ++i) {
      const auto& e = cfg_.tpdo[k].entries[i];
      tpdo_slots_[k][i] = add_object(e.index, e.sub, e.bits);
    }
    for (std::uint8_t i = 0; i < cfg_.rpdo[k].count; ++i) {
      const auto& e = cfg_.rpdo[k].entries[i];
      rpdo_slots_[k][i] = add_object(e.index, e.sub, e.bits);
    }
  }
  controlword_slot_ = slot(canopen::cia402::kControlword);
  statusword_slot_ = slot(canopen::cia402::kStatusword);
  target_position_slot_ = slot(canopen::cia402::kTargetPosition);
  build_node_config_script(cfg_, heartbeat_ms_, script_);
}

int NodeLink::add_object(std::uint16_t index, std::uint8_t sub, std::uint8_t bits) {
  const int existing = slot(index, sub);
  if (existing >= 0) return existing;
  if (object_count_ >= kMaxObjects) return -1;
  objects_[object_count_] = Object{index, sub, bits, 0};
  return static_cast<int>(object_count_++);
}

int NodeLink::slot(std::uint16_t index, std::uint8_t sub) const {
  for (std::size_t i = 0; i < object_count_; ++i) {
    if (objects_[i].index == index && objects_[i].sub == sub) return static_cast<int>(i);
  }
  return -1;
}

std::int64_t NodeLink::value(int s) const {
  return s >= 0 ? objects_[static_cast<std::size_t>(s)].value : 0;
}

void NodeLink::set_value(int s, std::int64_t v) {
  if (s >= 0) objects_[static_cast<std::size_t>(s)].value = v;
}

void NodeLink::start_boot(std::int64_t now_ns, hal::CanBus& bus) {
  step_ = 0;
  boot_error_ = 0;
  boot_state_ = BootState::kRunning;
  heartbeat_.disarm();
  sdo_.reset();
  start_step(now_ns, bus);
}

void NodeLink::start_step(std::int64_t now_ns, hal::CanBus& bus) {
  const ConfigStep& s = script_.steps[step_];
  if (s.write) {
    sdo_.start_write_u32(s.index, s.sub, s.value, s.size, now_ns, bus);
  } else {
    read_buffer_.fill(0);
    sdo_.start_read(s.index, s.sub, read_buffer_, now_ns, bus);
  }
}

void NodeLink::step_boot(std::int64_t now_ns, hal::CanBus& bus) {
  if (boot_state_ != BootState::kRunning) return;
  sdo_.poll(now_ns, bus);
  switch (sdo_.status()) {
    case canopen::SdoStatus::kBusy:
    case canopen::SdoStatus::kIdle:
      return;
    case canopen::SdoStatus::kTimedOut:
      boot_error_ = 'B';
      boot_state_ = BootState::kFailed;
      return;
    case canopen::SdoStatus::kAborted:
      boot_error_ = script_.steps[step_].error;
      boot_state_ = BootState::kFailed;
      return;
    case canopen::SdoStatus::kDone:
      break;
  }
  const ConfigStep& s = script_.steps[step_];
  if (!s.write && (static_cast<std::uint32_t>(sdo_.value()) & s.check_mask) != s.value) {
    boot_error_ = s.error;
    boot_state_ = BootState::kFailed;
    return;
  }
  sdo_.reset();
  if (++step_ >= script_.count) {
    boot_state_ = BootState::kConfigured;
    return;
  }
  start_step(now_ns, bus);
}

bool NodeLink::on_frame(const hal::CanFrame& f, std::int64_t now_ns, hal::CanBus& bus) {
  const std::uint16_t cob = f.cob_id();
  const std::uint8_t id = cfg_.node_id;
  if (cob == canopen::kHeartbeatBase + id) {
    if (f.dlc >= 1) heartbeat_.on_heartbeat(f.data[0], now_ns);
    return true;
  }
  if (cob == canopen::kSdoResponseBase + id) return sdo_.on_frame(f, now_ns, bus);
  if (cob == canopen::kEmcyBase + id) {
    if (f.dlc >= 2) {
      last_emcy_code_ = static_cast<std::uint16_t>(f.data[0] | (f.data[1] << 8));
      ++emcy_count_;
    }
    return true;
  }
  for (std::size_t k = 0; k < 4; ++k) {
    if (cob != canopen::kTpdoBase[k] + id || cfg_.tpdo[k].count == 0) continue;
    std::uint64_t raw[canopen::PdoMapping::kMaxEntries]{};
    if (!canopen::pdo_unpack(cfg_.tpdo[k], f.data.data(), f.dlc, raw)) {
      ++bad_pdo_;  // wrong length: counted, ignored
      return true;
    }
    for (std::uint8_t i = 0; i < cfg_.tpdo[k].count; ++i) {
      const int s = tpdo_slots_[k][i];
      if (s >= 0) set_value(s, canopen::sign_extend(raw[i], cfg_.tpdo[k].entries[i].bits));
    }
    last_tpdo_ns_[k] = now_ns;
    return true;
  }
  return false;
}

std::int64_t NodeLink::last_tpdo_ns() const {
  std::int64_t oldest = INT64_MAX;
  for (std::size_t k = 0; k < 4; ++k) {
    if (cfg_.tpdo[k].count > 0) oldest = std::min(oldest, last_tpdo_ns_[k]);
  }
  return oldest == INT64_MAX ? 0 : oldest;
}

void NodeLink::send_rpdos(hal::CanBus& bus) {
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& m = cfg_.rpdo[k];
    if (m.count == 0) continue;
    std::uint64_t raw[canopen::PdoMapping::kMaxEntries]{};
    for (std::uint8_t i = 0; i < m.count; ++i)
      raw[i] = static_cast<std::uint64_t>(value(rpdo_slots_[k][i]));
    hal::CanFrame f{};
    f.id = canopen::kRpdoBase[k] + cfg_.node_id;
    f.dlc = canopen::pdo_pack(m, raw, f.data.data());
    bus.send(f);
  }
}

State NodeLink::drive_state() const {
  return canopen::cia402::decode_state(static_cast<std::uint16_t>(value(statusword_slot_)));
}

void NodeLink::drive_towards(State wanted) {
  if (controlword_slot_ < 0) return;
  std::uint16_t cw = canopen::cia402::next_controlword(drive_state(), wanted, fault_reset_phase_);
  if (cw == canopen::cia402::controlword::kEnableOperation && target_position_slot_ >= 0) {
    // Profile position: change immediately, and a rising bit-4 edge every other cycle.
    setpoint_toggle_ = !setpoint_toggle_;
    cw |= canopen::cia402::controlword::kChangeImmediately;
    if (setpoint_toggle_) cw |= canopen::cia402::controlword::kNewSetPoint;
    set_value(target_position_slot_, pending_position_);
  }
  set_value(controlword_slot_, cw);
}

void NodeLink::set_position_target(std::int64_t counts) { pending_position_ = counts; }

}  // namespace planter
