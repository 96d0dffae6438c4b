#include "apps/planter-can/frame_decoder.h"

#include <cstdio>

#include "apps/planter-can/object_names.h"
#include "apps/planter-can/text_format.h"
#include "firmware/canopen/cia402.h"
#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/le_bytes.h"
#include "firmware/canopen/lss.h"
#include "firmware/canopen/pdo.h"
#include "firmware/io/signal_table.h"

namespace planter::cantool {
namespace {

const char* nmt_command_text(std::uint8_t cs) {
  switch (cs) {
    case 0x01:
      return "start";
    case 0x02:
      return "stop";
    case 0x80:
      return "enter pre-operational";
    case 0x81:
      return "reset node";
    case 0x82:
      return "reset communication";
    default:
      return "invalid command";
  }
}

std::string sdo_text(const hal::CanFrame& f, bool request) {
  if (f.dlc < 1) return "empty SDO frame";
  const std::uint8_t cmd = f.data[0];
  const bool mux = f.dlc >= 4;
  const std::uint16_t index = mux ? static_cast<std::uint16_t>(f.data[1] | (f.data[2] << 8)) : 0;
  const std::uint8_t sub = mux ? f.data[3] : 0;
  // The object's name beside its index (nothing when it is not a known object).
  const ObjectInfo* info = find_object(index, sub);
  const std::string_view label = info ? info->name : std::string_view("?");
  const int ll = static_cast<int>(label.size());
  if (cmd == 0x80) {
    const std::uint32_t code = f.dlc >= 8 ? canopen::read_le_u32(&f.data[4]) : 0;
    return format_text("abort %04X:%02X %.*s: 0x%08X %s", index, sub, ll, label.data(), code,
                       canopen::abort_code_text(code));
  }
  const std::uint8_t ccs = cmd >> 5;
  if (request) {
    switch (ccs) {
      case 1: {
        if ((cmd & 0x02) == 0)
          return format_text("write %04X:%02X %.*s (segmented)", index, sub, ll, label.data());
        const int n = (cmd & 0x01) ? 4 - ((cmd >> 2) & 3) : 4;
        std::uint32_t v = 0;
        for (int i = 0; i < n && 4 + i < f.dlc; ++i)
          v |= static_cast<std::uint32_t>(f.data[4 + i]) << (8 * i);
        return format_text("write %04X:%02X %.*s = %u (0x%X)", index, sub, ll, label.data(), v, v);
      }
      case 2:
        return format_text("read %04X:%02X %.*s", index, sub, ll, label.data());
      case 0:
        return "download segment";
      case 3:
        return "upload segment request";
      default:
        return format_text("SDO request 0x%02X", cmd);
    }
  }
  switch (ccs) {
    case 2: {
      if ((cmd & 0x02) == 0)
        return format_text("%04X:%02X %.*s (segmented upload)", index, sub, ll, label.data());
      const int n = (cmd & 0x01) ? 4 - ((cmd >> 2) & 3) : 4;
      std::uint32_t v = 0;
      for (int i = 0; i < n && 4 + i < f.dlc; ++i)
        v |= static_cast<std::uint32_t>(f.data[4 + i]) << (8 * i);
      return format_text("%04X:%02X %.*s = %u (0x%X)", index, sub, ll, label.data(), v, v);
    }
    case 3:
      return format_text("write %04X:%02X %.*s ok", index, sub, ll, label.data());
    case 0:
      return "upload segment";
    case 1:
      return "download segment ok";
    default:
      return format_text("SDO response 0x%02X", cmd);
  }
}

}  // namespace

const char* service_name(Service s) {
  switch (s) {
    case Service::kNmt:
      return "NMT";
    case Service::kSync:
      return "SYNC";
    case Service::kEmcy:
      return "EMCY";
    case Service::kTpdo:
      return "TPDO";
    case Service::kRpdo:
      return "RPDO";
    case Service::kSdoRequest:
      return "SDO-rx";
    case Service::kSdoResponse:
      return "SDO-tx";
    case Service::kHeartbeat:
      return "HB";
    case Service::kLssMaster:
      return "LSS-m";
    case Service::kLssSlave:
      return "LSS-s";
    case Service::kOther:
      return "other";
    case Service::kErrorFrame:
      return "ERROR";
    case Service::kExtended:
      return "EXT";
    case Service::kRemote:
      return "RTR";
  }
  return "?";
}

std::string raw_frame_text(const hal::CanFrame& f) {
  std::string s = (f.id & hal::CanFrame::kExtendedFlag) ? format_text("%08X", f.id & 0x1FFFFFFFu)
                                                        : format_text("%03X", f.id & 0x7FFu);
  s += format_text("  [%u] ", f.dlc);
  for (int i = 0; i < f.dlc && i < 8; ++i)
    s += format_text(" %02X", f.data[static_cast<std::size_t>(i)]);
  return s;
}

std::optional<ProcessValue> scale_process_value(const NodeConfig& node, std::uint16_t index,
                                                std::uint8_t sub, std::int64_t raw) {
  namespace c402 = canopen::cia402;
  ProcessValue v;
  v.index = index;
  v.sub = sub;
  v.raw = raw;
  const auto r = static_cast<double>(raw);
  // A signal of the machine: its scale, unit and name come from the signal table.
  if (const SignalDecl* s = find_bus_signal(node.role, index, sub)) {
    v.value = bus_to_si(s->scale, node, r);
    v.unit = s->unit;
    v.name = std::string(s->column);
    return v;
  }
  // Another CiA 402 object mapped by the board: scaled as its kind, in the node's unit.
  if (node.profile != 402) return std::nullopt;
  if (const ObjectInfo* o = find_object(index, sub)) v.name = std::string(o->name);
  const bool disc = node.role == NodeRole::kDiscDrive;
  switch (index) {
    case c402::kPositionActual:
    case c402::kTargetPosition:
      v.value = bus_to_si(BusScale::kPerCount, node, r);
      v.unit = disc ? "rad" : "mm";
      return v;
    case c402::kVelocityActual:
    case c402::kTargetVelocity:
    case c402::kProfileVelocity:
      v.value = bus_to_si(BusScale::kPerCount, node, r);
      v.unit = disc ? "rad/s" : "mm/s";
      return v;
    case c402::kTorqueActual:
      v.value = bus_to_si(BusScale::kPerMilleRated, node, r);
      v.unit = disc ? "N*m" : "N";
      return v;
    default:
      return std::nullopt;
  }
}

const NodeConfig* FrameDecoder::node_config(std::uint8_t node_id) const {
  if (board_ == nullptr) return nullptr;
  for (const auto& n : board_->nodes) {
    if (n.node_id == node_id) return &n;
  }
  return nullptr;
}

void FrameDecoder::decode_pdo(const hal::CanFrame& f, DecodedFrame& out, bool transmit,
                              int k) const {
  const NodeConfig* node = node_config(out.node);
  const canopen::PdoMapping* map =
      node ? &(transmit ? node->tpdo : node->rpdo)[static_cast<std::size_t>(k)] : nullptr;
  if (map == nullptr || map->count == 0) {
    out.text = format_text("%s%d (not in the board file)", transmit ? "TPDO" : "RPDO", k + 1);
    return;
  }
  std::uint64_t raw[canopen::PdoMapping::kMaxEntries]{};
  if (!canopen::pdo_unpack(*map, f.data.data(), f.dlc, raw)) {
    out.malformed = true;
    out.text = format_text("%s%d: %u bytes, the board maps %d", transmit ? "TPDO" : "RPDO", k + 1,
                           f.dlc, map->total_bits() / 8);
    return;
  }
  out.text.clear();
  for (std::uint8_t i = 0; i < map->count; ++i) {
    const auto& e = map->entries[i];
    const std::int64_t value = canopen::sign_extend(raw[i], e.bits);
    ProcessValue pv;
    if (auto scaled = scale_process_value(*node, e.index, e.sub, value)) {
      pv = *scaled;
      out.text += format_text("%s%s %.4g %.*s", i ? ", " : "", pv.name.c_str(), pv.value,
                              static_cast<int>(pv.unit.size()), pv.unit.data());
    } else {
      pv.index = e.index;
      pv.sub = e.sub;
      pv.raw = value;
      pv.value = static_cast<double>(value);
      char buf[64];
      pv.name = std::string(object_label(e.index, e.sub, buf, sizeof buf));
      if (e.index == canopen::cia402::kStatusword) {
        out.text += format_text("%s%s 0x%04llX (%s)", i ? ", " : "", pv.name.c_str(),
                                static_cast<unsigned long long>(raw[i]),
                                canopen::cia402::state_name(canopen::cia402::decode_state(
                                    static_cast<std::uint16_t>(raw[i]))));
      } else {
        out.text += format_text("%s%s 0x%llX", i ? ", " : "", pv.name.c_str(),
                                static_cast<unsigned long long>(raw[i]));
      }
    }
    out.values.push_back(std::move(pv));
  }
}

DecodedFrame FrameDecoder::decode(const hal::CanFrame& f) const {
  DecodedFrame out;
  if (f.id & hal::CanFrame::kErrorFlag) {
    out.service = Service::kErrorFrame;
    out.text = format_text("error frame, class 0x%X", f.id & 0x1FFFFFFFu);
    return out;
  }
  if (f.id & hal::CanFrame::kExtendedFlag) {
    out.service = Service::kExtended;
    out.text = "extended frame (not CANopen)";
    return out;
  }
  if (f.id & hal::CanFrame::kRemoteFlag) {
    out.service = Service::kRemote;
    out.text = "remote request";
    return out;
  }
  if (f.dlc > 8) {
    out.malformed = true;
    out.text = "DLC above 8";
    return out;
  }
  const std::uint16_t cob = f.cob_id();
  const auto fn = static_cast<std::uint16_t>(cob & 0x780);
  const auto node = static_cast<std::uint8_t>(cob & 0x7F);
  if (cob == canopen::kNmtCobId) {
    out.service = Service::kNmt;
    if (f.dlc < 2) {
      out.malformed = true;
      out.text = "NMT with fewer than 2 bytes";
      return out;
    }
    out.node = f.data[1];
    out.text = format_text("%s %s", nmt_command_text(f.data[0]),
                           f.data[1] ? format_text("node %u", f.data[1]).c_str() : "all nodes");
    return out;
  }
  if (cob == canopen::kSyncCobId) {
    out.service = Service::kSync;
    out.text = f.dlc >= 1 ? format_text("SYNC counter %u", f.data[0]) : "SYNC";
    return out;
  }
  if (cob == canopen::kLssMasterCobId || cob == canopen::kLssSlaveCobId) {
    out.service = cob == canopen::kLssMasterCobId ? Service::kLssMaster : Service::kLssSlave;
    out.text = f.dlc >= 1 ? format_text("LSS cs 0x%02X", f.data[0]) : "LSS (empty)";
    out.malformed = f.dlc < 1;
    return out;
  }
  out.node = node;
  if (const NodeConfig* n = node_config(node)) out.node_name = node_role_name(n->role);
  if (node == 0) {
    out.service = Service::kOther;
    out.text = "unknown COB-ID";
    return out;
  }
  if (fn == canopen::kEmcyBase) {
    out.service = Service::kEmcy;
    if (f.dlc < 3) {
      out.malformed = true;
      out.text = "EMCY with fewer than 3 bytes";
      return out;
    }
    const auto code = static_cast<std::uint16_t>(f.data[0] | (f.data[1] << 8));
    out.text =
        format_text("EMCY 0x%04X %s, error register 0x%02X", code, emcy_code_text(code), f.data[2]);
    return out;
  }
  if (fn == canopen::kHeartbeatBase) {
    out.service = Service::kHeartbeat;
    if (f.dlc < 1) {
      out.malformed = true;
      out.text = "heartbeat without a state byte";
      return out;
    }
    out.text = nmt_state_name(f.data[0] & 0x7F);
    return out;
  }
  if (fn == canopen::kSdoResponseBase || fn == canopen::kSdoRequestBase) {
    const bool request = fn == canopen::kSdoRequestBase;
    out.service = request ? Service::kSdoRequest : Service::kSdoResponse;
    out.malformed = f.dlc < 1;
    out.text = sdo_text(f, request);
    return out;
  }
  for (int k = 0; k < 4; ++k) {
    if (fn == canopen::kTpdoBase[k]) {
      out.service = Service::kTpdo;
      out.pdo = k + 1;
      decode_pdo(f, out, true, k);
      return out;
    }
    if (fn == canopen::kRpdoBase[k]) {
      out.service = Service::kRpdo;
      out.pdo = k + 1;
      decode_pdo(f, out, false, k);
      return out;
    }
  }
  out.service = Service::kOther;
  out.text = "unknown COB-ID";
  return out;
}

}  // namespace planter::cantool
