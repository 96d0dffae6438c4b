#include "firmware/controller/node_link.h"

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
  build_script();
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

void NodeLink::add_step(const Step& step) {
  if (step_count_ < kMaxSteps) steps_[step_count_++] = step;
}

void NodeLink::build_script() {
  // Identity first (CiA 302-2): no answer = B, wrong profile = C, wrong vendor = D, product = M.
  add_step({false, 0x1000, 0, 4, cfg_.profile, 0xFFFF, 'C'});
  if (cfg_.vendor_id != 0) add_step({false, 0x1018, 1, 4, cfg_.vendor_id, 0xFFFFFFFF, 'D'});
  if (cfg_.product_code != 0) add_step({false, 0x1018, 2, 4, cfg_.product_code, 0xFFFFFFFF, 'M'});
  if (cfg_.profile == 402) {
    const bool velocity = cfg_.role == NodeRole::kDiscDrive;
    add_step({true, canopen::cia402::kModesOfOperation, 0, 1,
              static_cast<std::uint32_t>(velocity ? canopen::cia402::kModeProfileVelocity
                                                  : canopen::cia402::kModeProfilePosition),
              0, 'J'});
    if (!velocity && cfg_.profile_velocity_units_per_s > 0) {
      add_step(
          {true, canopen::cia402::kProfileVelocity, 0, 4,
           static_cast<std::uint32_t>(cfg_.profile_velocity_units_per_s * cfg_.counts_per_unit), 0,
           'J'});
    }
  }
  // PDO configuration in the order CiA 301 requires: invalidate, clear, map, count, validate.
  auto configure = [this](std::uint16_t comm, std::uint16_t map, std::uint16_t cob,
                          const canopen::PdoMapping& m, std::uint8_t transmission) {
    add_step({true, comm, 1, 4, 0x80000000u | cob, 0, 'J'});
    if (m.count == 0) return;  // left invalid
    add_step({true, map, 0, 1, 0, 0, 'J'});
    for (std::uint8_t i = 0; i < m.count; ++i) {
      add_step(
          {true, map, static_cast<std::uint8_t>(i + 1), 4, m.entries[i].mapping_value(), 0, 'J'});
    }
    add_step({true, map, 0, 1, m.count, 0, 'J'});
    add_step({true, comm, 2, 1, transmission, 0, 'J'});
    add_step({true, comm, 1, 4, cob, 0, 'J'});
  };
  for (std::uint16_t k = 0; k < 4; ++k) {
    configure(static_cast<std::uint16_t>(0x1800 + k), static_cast<std::uint16_t>(0x1A00 + k),
              static_cast<std::uint16_t>(canopen::kTpdoBase[k] + cfg_.node_id), cfg_.tpdo[k], 1);
    configure(static_cast<std::uint16_t>(0x1400 + k), static_cast<std::uint16_t>(0x1600 + k),
              static_cast<std::uint16_t>(canopen::kRpdoBase[k] + cfg_.node_id), cfg_.rpdo[k], 255);
  }
  // Heartbeat last, so its watch starts from a configured node.
  add_step({true, 0x1017, 0, 2, heartbeat_ms_, 0, 'K'});
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
  const Step& s = steps_[step_];
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
      boot_error_ = steps_[step_].error;
      boot_state_ = BootState::kFailed;
      return;
    case canopen::SdoStatus::kDone:
      break;
  }
  const Step& s = steps_[step_];
  if (!s.write && (static_cast<std::uint32_t>(sdo_.value()) & s.check_mask) != s.value) {
    boot_error_ = s.error;
    boot_state_ = BootState::kFailed;
    return;
  }
  sdo_.reset();
  if (++step_ >= step_count_) {
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
    last_tpdo_ns_ = now_ns;
    return true;
  }
  return false;
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
