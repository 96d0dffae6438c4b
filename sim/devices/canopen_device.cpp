#include "sim/devices/canopen_device.h"

#include <algorithm>

namespace planter::sim {

using canopen::Access;

CanopenDevice::CanopenDevice(const DeviceIdentity& id, hal::CanBus& bus)
    : identity_(id),
      bus_(bus),
      sdo_(id.node_id, od_, this),
      lss_({id.vendor_id, id.product_code, id.revision, id.serial}, id.node_id) {
  od_.add(0x1000, 0, 4, Access::kConst, id.device_type);
  od_.add(0x1001, 0, 1, Access::kReadOnly, 0);
  od_.add(0x1003, 0, 1, Access::kReadWrite, 0);  // error history: count; write 0 clears
  for (std::uint8_t s = 1; s <= kErrorHistoryDepth; ++s) od_.add(0x1003, s, 4, Access::kReadOnly);
  od_.add_string(0x1008, 0, id.name);
  od_.add_string(0x1009, 0, "sim-1");
  od_.add_string(0x100A, 0, "0.1.0");
  od_.add(0x1005, 0, 4, Access::kReadWrite, canopen::kSyncCobId);
  od_.add(0x1010, 1, 4, Access::kReadWrite, 1);
  od_.add(0x1017, 0, 2, Access::kReadWrite, 0);
  od_.add(0x1018, 0, 1, Access::kConst, 4);
  od_.add(0x1018, 1, 4, Access::kConst, id.vendor_id);
  od_.add(0x1018, 2, 4, Access::kConst, id.product_code);
  od_.add(0x1018, 3, 4, Access::kConst, id.revision);
  od_.add(0x1018, 4, 4, Access::kConst, id.serial);
  for (std::uint16_t k = 0; k < 4; ++k) {
    for (std::uint16_t comm :
         {static_cast<std::uint16_t>(0x1400 + k), static_cast<std::uint16_t>(0x1800 + k)}) {
      od_.add(comm, 0, 1, Access::kConst, 5);
      od_.add(comm, 1, 4, Access::kReadWrite, 0);
      od_.add(comm, 2, 1, Access::kReadWrite, 255);
      od_.add(comm, 3, 2, Access::kReadWrite, 0);
      od_.add(comm, 5, 2, Access::kReadWrite, 0);
    }
    for (std::uint16_t map :
         {static_cast<std::uint16_t>(0x1600 + k), static_cast<std::uint16_t>(0x1A00 + k)}) {
      od_.add(map, 0, 1, Access::kReadWrite, 0);
      for (std::uint8_t s = 1; s <= 8; ++s) od_.add(map, s, 4, Access::kReadWrite, 0);
    }
  }
  reset_communication(0);
}

namespace {

// 0x1010:1 takes only this signature ("save", CiA 301 7.5.2.13).
constexpr std::uint64_t kSaveSignature = 0x65766173;
constexpr std::uint32_t kPdoInvalid = 0x80000000u;

bool is_mapping_object(std::uint16_t index) {
  return (index >= 0x1600 && index <= 0x1603) || (index >= 0x1A00 && index <= 0x1A03);
}

bool is_pdo_comm_object(std::uint16_t index) {
  return (index >= 0x1400 && index <= 0x1403) || (index >= 0x1800 && index <= 0x1803);
}

bool is_comm_object(std::uint16_t index) {
  return index == 0x1017 || is_pdo_comm_object(index) || is_mapping_object(index);
}

// The communication object (0x14xx/0x18xx) of a mapping object (0x16xx/0x1Axx).
std::uint16_t comm_of_mapping(std::uint16_t map_index) {
  return static_cast<std::uint16_t>(map_index - 0x200);
}

}  // namespace

std::uint32_t CanopenDevice::check_write(const canopen::ObjectEntry& entry,
                                         std::uint64_t value) const {
  namespace ac = canopen::abort_code;
  if (entry.index == 0x1010 && entry.sub == 1)
    return value == kSaveSignature ? 0 : ac::kCannotStore;
  if (entry.index == 0x1003 && entry.sub == 0) return value == 0 ? 0 : ac::kValueRange;
  if (is_mapping_object(entry.index)) return check_mapping_write(entry, value);
  if (is_pdo_comm_object(entry.index) && entry.sub == 1) {
    // CiA 301 7.5.2.35: the COB-ID of a valid PDO cannot change; invalidate it first.
    const std::uint64_t now = entry.value;
    const bool valid_now = (now & kPdoInvalid) == 0;
    const bool stays_valid = (value & kPdoInvalid) == 0;
    if (valid_now && stays_valid && (value & 0x7FF) != (now & 0x7FF)) return ac::kValueRange;
    if (stays_valid && (value & 0x7FF) == 0) return ac::kValueRange;
  }
  if (is_pdo_comm_object(entry.index) && entry.sub == 2) {
    if (value > 240 && value < 254) return ac::kValueRange;  // 241-253 reserved
  }
  return check_profile_write(entry, value);
}

std::uint32_t CanopenDevice::check_mapping_write(const canopen::ObjectEntry& entry,
                                                 std::uint64_t value) const {
  namespace ac = canopen::abort_code;
  // CiA 301 7.5.2.36: a mapping changes only while its PDO is invalid, and its entries only
  // while sub 0 is 0; sub 0 is then set to the number of entries, each checked again.
  const auto comm = comm_of_mapping(entry.index);
  if ((od_.get(comm, 1) & kPdoInvalid) == 0) return ac::kUnsupportedAccess;
  const bool receive = entry.index < 0x1A00;
  if (entry.sub != 0) {
    if (od_.get(entry.index, 0) != 0) return ac::kUnsupportedAccess;
    return value == 0 ? 0 : check_mapped_object(static_cast<std::uint32_t>(value), receive);
  }
  if (value > canopen::PdoMapping::kMaxEntries) return ac::kMapLength;
  unsigned bits = 0;
  for (std::uint8_t i = 1; i <= value; ++i) {
    const auto mapped = static_cast<std::uint32_t>(od_.get(entry.index, i));
    if (const auto code = check_mapped_object(mapped, receive); code != 0) return code;
    bits += mapped & 0xFF;
  }
  return bits <= 8 * canopen::kPdoMaxBytes ? 0 : ac::kMapLength;
}

std::uint32_t CanopenDevice::check_mapped_object(std::uint32_t mapping_value, bool receive) const {
  namespace ac = canopen::abort_code;
  const auto e = canopen::PdoEntry::from_mapping_value(mapping_value);
  const canopen::ObjectEntry* object = od_.find(e.index, e.sub);
  if (object == nullptr) return od_.has_index(e.index) ? ac::kNoSubIndex : ac::kNoObject;
  // This device maps whole numeric objects only (8, 16 or 32 bits).
  if (object->size == 0 || object->size > 4 || e.bits != 8 * object->size) return ac::kCannotMap;
  const bool readable = object->access != canopen::Access::kWriteOnly;
  const bool writable = object->access == canopen::Access::kReadWrite ||
                        object->access == canopen::Access::kWriteOnly;
  if (receive ? !writable : !readable) return ac::kCannotMap;
  return 0;
}

void CanopenDevice::set_node_id(std::uint8_t node_id) {
  identity_.node_id = node_id;
  sdo_.set_node_id(node_id);
}

void CanopenDevice::reset_communication(std::int64_t now_ns) {
  set_node_id(lss_.active_node_id());
  nmt_ = canopen::NmtState::kPreOperational;
  next_heartbeat_ns_ = now_ns;
  if (!stored_comm_.empty()) {
    for (const auto& e : stored_comm_) od_.set(e.index, e.sub, e.value);
    return;
  }
  // Default connection set, every PDO invalid until the master configures it.
  for (std::uint16_t k = 0; k < 4; ++k) {
    od_.set(static_cast<std::uint16_t>(0x1400 + k), 1,
            0x80000000u | (canopen::kRpdoBase[k] + identity_.node_id));
    od_.set(static_cast<std::uint16_t>(0x1800 + k), 1,
            0x80000000u | (canopen::kTpdoBase[k] + identity_.node_id));
    od_.set(static_cast<std::uint16_t>(0x1600 + k), 0, 0);
    od_.set(static_cast<std::uint16_t>(0x1A00 + k), 0, 0);
  }
  od_.set(0x1017, 0, 0);
}

void CanopenDevice::after_sdo_write() {
  // 0x1010:1 = "save" stores the communication parameters; the entry reads 1 again after.
  if (od_.get(0x1010, 1) == kSaveSignature) {
    stored_comm_.clear();
    for (std::uint16_t index = 0x1017; index <= 0x1A03; ++index) {
      if (!is_comm_object(index)) continue;
      for (std::uint8_t sub = 0; sub <= 8; ++sub) {
        if (const auto* e = od_.find(index, sub)) stored_comm_.push_back(*e);
      }
    }
    od_.set(0x1010, 1, 1);
  }
  if (od_.get(0x1003, 0) != 0) od_.set(0x1003, 0, error_count_);  // only 0 may be written
  error_count_ = static_cast<std::uint8_t>(od_.get(0x1003, 0));
}

void CanopenDevice::power_on(std::int64_t now_ns) {
  reset_communication(now_ns);
  if (unconfigured()) return;  // silent until LSS gives it an ID
  send_heartbeat(static_cast<std::uint8_t>(canopen::NmtState::kBootUp));
}

void CanopenDevice::send_heartbeat(std::uint8_t state) {
  hal::CanFrame f{};
  f.id = canopen::kHeartbeatBase + identity_.node_id;
  f.dlc = 1;
  f.data[0] = state;
  bus_.send(f);
}

void CanopenDevice::send_emcy(std::uint16_t code, std::uint8_t error_register) {
  hal::CanFrame f{};
  f.id = canopen::kEmcyBase + identity_.node_id;
  f.dlc = 8;
  f.data[0] = static_cast<std::uint8_t>(code);
  f.data[1] = static_cast<std::uint8_t>(code >> 8);
  f.data[2] = error_register;
  od_.set(0x1001, 0, error_register);
  if (code != 0) {
    // Newest first in 0x1003:1.
    for (std::uint8_t s = kErrorHistoryDepth; s > 1; --s)
      od_.set(0x1003, s, od_.get(0x1003, s - 1));
    od_.set(0x1003, 1, code);
    if (error_count_ < kErrorHistoryDepth) ++error_count_;
    od_.set(0x1003, 0, error_count_);
  }
  if (unconfigured()) return;
  bus_.send(f);
}

void CanopenDevice::process(std::int64_t now_ns) {
  hal::CanFrame f;
  while (bus_.receive(f)) handle(f, now_ns);
  if (sdo_.writes() != sdo_writes_seen_) {
    sdo_writes_seen_ = sdo_.writes();
    after_sdo_write();
    on_rpdo();  // the application sees SDO-written commands too (commissioning moves)
  }
  if (unconfigured()) return;
  resolve_if_changed();
  const auto period_ms = heartbeat_period_ms_ != nullptr ? heartbeat_period_ms_->value : 0;
  if (period_ms > 0 && now_ns >= next_heartbeat_ns_) {
    send_heartbeat(static_cast<std::uint8_t>(nmt_));
    next_heartbeat_ns_ = now_ns + static_cast<std::int64_t>(period_ms) * 1'000'000;
  }
}

canopen::PdoMapping CanopenDevice::mapping(std::uint16_t map_index) const {
  canopen::PdoMapping m;
  m.count = static_cast<std::uint8_t>(std::min<std::uint64_t>(od_.get(map_index, 0), 8));
  for (std::uint8_t i = 0; i < m.count; ++i) {
    m.entries[i] = canopen::PdoEntry::from_mapping_value(
        static_cast<std::uint32_t>(od_.get(map_index, i + 1)));
  }
  return m;
}

void CanopenDevice::resolve_if_changed() {
  if (od_.revision() == resolved_revision_) return;
  const auto resolve = [this](std::uint16_t comm, ResolvedPdo& pdo) {
    const auto cob_entry = od_.get(comm, 1);
    pdo.valid = (cob_entry & kPdoInvalid) == 0;
    pdo.cob_id = static_cast<std::uint16_t>(cob_entry & 0x7FF);
    pdo.transmission_type = od_.get(comm, 2);
    pdo.mapping = mapping(static_cast<std::uint16_t>(comm + 0x200));
    for (std::uint8_t i = 0; i < pdo.mapping.count; ++i) {
      const auto& e = pdo.mapping.entries[i];
      pdo.objects[i] = od_.find(e.index, e.sub);
    }
  };
  for (std::uint16_t k = 0; k < 4; ++k) {
    resolve(static_cast<std::uint16_t>(0x1400 + k), rpdos_[k]);
    resolve(static_cast<std::uint16_t>(0x1800 + k), tpdos_[k]);
  }
  heartbeat_period_ms_ = od_.find(0x1017, 0);
  resolved_revision_ = od_.revision();
}

void CanopenDevice::handle(const hal::CanFrame& f, std::int64_t now_ns) {
  if (!f.is_standard_data()) return;
  const std::uint16_t cob = f.cob_id();
  if (cob == canopen::kLssMasterCobId) {
    if (lss_.on_frame(f, bus_) == canopen::LssSlave::Event::kActivateNodeId) {
      lss_.reset_communication();
      power_on(now_ns);
    }
    return;
  }
  if (unconfigured()) return;
  if (cob == canopen::kNmtCobId) {
    if (f.dlc < 2 || (f.data[1] != 0 && f.data[1] != identity_.node_id)) return;
    switch (static_cast<canopen::NmtCommand>(f.data[0])) {
      case canopen::NmtCommand::kStart:
        nmt_ = canopen::NmtState::kOperational;
        break;
      case canopen::NmtCommand::kStop:
        nmt_ = canopen::NmtState::kStopped;
        break;
      case canopen::NmtCommand::kPreOperational:
        nmt_ = canopen::NmtState::kPreOperational;
        break;
      case canopen::NmtCommand::kResetNode:
        on_reset();
        lss_.reset_communication();
        power_on(now_ns);
        break;
      case canopen::NmtCommand::kResetCommunication:
        lss_.reset_communication();
        power_on(now_ns);
        break;
    }
    return;
  }
  if (nmt_ != canopen::NmtState::kStopped && sdo_.on_frame(f, bus_)) return;
  if (nmt_ != canopen::NmtState::kOperational) return;
  if (cob == canopen::kSyncCobId) {
    on_sync();
    return;
  }
  resolve_if_changed();
  for (const ResolvedPdo& pdo : rpdos_) {
    if (!pdo.valid || pdo.cob_id != cob) continue;
    std::uint64_t raw[canopen::PdoMapping::kMaxEntries]{};
    if (!canopen::pdo_unpack(pdo.mapping, f.data.data(), f.dlc, raw)) return;  // short: ignored
    const ResolvedPdo copy = pdo;  // a mapped communication object re-resolves the tables
    for (std::uint8_t i = 0; i < copy.mapping.count; ++i) {
      if (copy.objects[i] != nullptr) od_.store(*copy.objects[i], raw[i]);
    }
    on_rpdo();
    return;
  }
}

void CanopenDevice::on_sync() {
  ++sync_count_;
  resolve_if_changed();
  for (const ResolvedPdo& pdo : tpdos_) {
    if (!pdo.valid) continue;
    const auto type = pdo.transmission_type;
    if (type == 0 || type > 240 || sync_count_ % type != 0) continue;
    std::uint64_t raw[canopen::PdoMapping::kMaxEntries]{};
    for (std::uint8_t i = 0; i < pdo.mapping.count; ++i)
      raw[i] = pdo.objects[i] != nullptr ? pdo.objects[i]->value : 0;
    hal::CanFrame f{};
    f.id = pdo.cob_id;
    f.dlc = canopen::pdo_pack(pdo.mapping, raw, f.data.data());
    bus_.send(f);
  }
}

}  // namespace planter::sim
