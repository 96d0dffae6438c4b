#include "firmware/canopen/lss.h"

#include "firmware/canopen/le_bytes.h"

namespace planter::canopen {
hal::CanFrame lss_frame(std::uint16_t cob_id, std::uint8_t cs, std::uint32_t value) {
  hal::CanFrame f{};
  f.id = cob_id;
  f.dlc = 8;
  f.data[0] = cs;
  write_le_u32(&f.data[1], value);
  return f;
}

void LssSlave::reply(std::uint8_t cs, std::uint32_t value, hal::CanBus& bus) {
  bus.send(lss_frame(kLssSlaveCobId, cs, value));
}

LssSlave::Event LssSlave::on_frame(const hal::CanFrame& f, hal::CanBus& bus) {
  if (!f.is_standard_data() || f.cob_id() != kLssMasterCobId || f.dlc < 1) return Event::kNone;
  const std::uint8_t cs = f.data[0];
  const std::uint8_t* d = f.data.data();
  if (cs == lss_cs::kSwitchGlobal && f.dlc >= 2) {
    const bool was_configuring = configuring_;
    configuring_ = d[1] == 1;
    selective_matched_ = 0;
    if (was_configuring && !configuring_ && active_id_ == kUnconfiguredNodeId &&
        pending_id_ != kUnconfiguredNodeId) {
      return Event::kActivateNodeId;
    }
    return Event::kHandled;
  }
  if (cs >= lss_cs::kSwitchSelectiveVendor && cs <= lss_cs::kSwitchSelectiveVendor + 3 &&
      f.dlc >= 5) {
    const std::uint8_t part = cs - lss_cs::kSwitchSelectiveVendor;
    // The four parts come in order; a mismatch anywhere starts over.
    if (part == selective_matched_ && read_le_u32(&d[1]) == identity_[part]) {
      ++selective_matched_;
    } else {
      selective_matched_ = 0;
    }
    if (selective_matched_ == 4) {
      selective_matched_ = 0;
      configuring_ = true;
      reply(lss_cs::kSwitchSelectiveReply, 0, bus);
    }
    return Event::kHandled;
  }
  if (cs == lss_cs::kFastscan && f.dlc >= 8) {
    // Only unconfigured nodes in waiting state take part.
    if (configuring_ || active_id_ != kUnconfiguredNodeId) return Event::kHandled;
    const std::uint32_t id_number = read_le_u32(&d[1]);
    const std::uint8_t bit_checked = d[5];
    const std::uint8_t sub = d[6];
    const std::uint8_t next = d[7];
    if (bit_checked == lss_cs::kFastscanReset) {
      fastscan_pos_ = 0;
      reply(lss_cs::kFastscanReply, 0, bus);
      return Event::kHandled;
    }
    if (bit_checked > 31 || sub > 3 || sub != fastscan_pos_) return Event::kHandled;
    const std::uint32_t mask = bit_checked == 31 ? 0x80000000u : ~((1u << bit_checked) - 1u);
    if (((identity_[sub] ^ id_number) & mask) != 0) return Event::kHandled;
    reply(lss_cs::kFastscanReply, 0, bus);
    if (bit_checked == 0) {
      if (sub == 3) configuring_ = true;
      fastscan_pos_ = next & 3u;
    }
    return Event::kHandled;
  }
  if (!configuring_) return Event::kHandled;
  switch (cs) {
    case lss_cs::kConfigureNodeId: {
      const std::uint8_t id = f.dlc >= 2 ? d[1] : 0;
      const bool ok = (id >= 1 && id <= 127) || id == kUnconfiguredNodeId;
      if (ok) pending_id_ = id;
      reply(lss_cs::kConfigureNodeId, ok ? 0u : 1u, bus);
      break;
    }
    case lss_cs::kConfigureBitTiming:
      reply(lss_cs::kConfigureBitTiming, 1u, bus);  // bit timing is fixed on this bus
      break;
    case lss_cs::kStore:
      stored_id_ = pending_id_;
      reply(lss_cs::kStore, 0u, bus);
      break;
    case lss_cs::kInquireNodeId:
      reply(lss_cs::kInquireNodeId, active_id_, bus);
      break;
    default:
      if (cs >= lss_cs::kInquireVendor && cs <= lss_cs::kInquireVendor + 3)
        reply(cs, identity_[cs - lss_cs::kInquireVendor], bus);
      break;
  }
  return Event::kHandled;
}

}  // namespace planter::canopen
