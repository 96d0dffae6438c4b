#include "apps/planter-can/cmd_lss.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <ostream>

#include "apps/planter-can/sdo_session.h"
#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/lss.h"
#include "firmware/canopen/nmt.h"

namespace planter::cantool {
namespace {

namespace cs = canopen::lss_cs;

void send_lss(ToolLink& link, std::uint8_t command, std::uint32_t value = 0, std::uint8_t b5 = 0,
              std::uint8_t b6 = 0, std::uint8_t b7 = 0) {
  hal::CanFrame f = canopen::lss_frame(canopen::kLssMasterCobId, command, value);
  f.data[5] = b5;
  f.data[6] = b6;
  f.data[7] = b7;
  link.send(f);
}

// The first reply with command specifier `want` before the timeout; other frames are ignored.
std::optional<hal::CanFrame> await_lss(ToolLink& link, std::uint8_t want, std::int64_t timeout_ns) {
  const std::int64_t deadline = link.now_ns() + timeout_ns;
  hal::CanFrame f;
  while (link.receive_until(f, deadline)) {
    if (f.is_standard_data() && f.cob_id() == canopen::kLssSlaveCobId && f.dlc >= 1 &&
        f.data[0] == want)
      return f;
  }
  return std::nullopt;
}

bool switch_selective(ToolLink& link, const std::array<std::uint32_t, 4>& id, std::int64_t t) {
  for (std::uint8_t i = 0; i < 4; ++i)
    send_lss(link, static_cast<std::uint8_t>(cs::kSwitchSelectiveVendor + i), id[i]);
  return await_lss(link, cs::kSwitchSelectiveReply, t).has_value();
}

std::string identity_text(const std::array<std::uint32_t, 4>& id) {
  char b[128];
  std::snprintf(b, sizeof b, "vendor 0x%08X product 0x%08X revision 0x%08X serial 0x%08X", id[0],
                id[1], id[2], id[3]);
  return b;
}

}  // namespace

std::optional<std::array<std::uint32_t, 4>> lss_fastscan(ToolLink& link, std::int64_t timeout_ns,
                                                         int& rounds) {
  rounds = 1;
  send_lss(link, cs::kFastscan, 0, cs::kFastscanReset, 0, 0);
  if (!await_lss(link, cs::kFastscanReply, timeout_ns)) return std::nullopt;  // nobody unconfigured
  std::array<std::uint32_t, 4> id{};
  for (std::uint8_t sub = 0; sub < 4; ++sub) {
    std::uint32_t value = 0;
    for (int bit = 31; bit >= 1; --bit) {
      ++rounds;
      // Anyone whose bits 31..bit equal `value` (with this bit 0) answers; silence: it is 1.
      send_lss(link, cs::kFastscan, value, static_cast<std::uint8_t>(bit), sub, sub);
      if (!await_lss(link, cs::kFastscanReply, timeout_ns)) value |= 1u << bit;
    }
    // Bit 0 with BitChecked 0 also moves the node on to the next part (or, after the serial
    // number, into configuration state): try 0, then 1.
    const auto next = static_cast<std::uint8_t>((sub + 1) & 3);
    bool matched = false;
    for (std::uint32_t bit0 = 0; bit0 <= 1 && !matched; ++bit0) {
      ++rounds;
      send_lss(link, cs::kFastscan, value | bit0, 0, sub, next);
      matched = await_lss(link, cs::kFastscanReply, timeout_ns).has_value();
      if (matched) value |= bit0;
    }
    if (!matched) return std::nullopt;  // the node went away mid-scan
    id[sub] = value;
  }
  return id;
}

namespace {

using Identity = std::array<std::uint32_t, 4>;

// The node with --identity switched into configuration state, or false after saying none
// answered.
bool select_by_identity(ToolContext& ctx, const LssOptions& opt) {
  if (switch_selective(ctx.link, *opt.identity, opt.timeout_ns)) return true;
  ctx.err << "planter-can: lss: no node with " << identity_text(*opt.identity) << " answered\n";
  return false;
}

// inquire: the node-ID of the node with the given identity.
int inquire(ToolContext& ctx, const LssOptions& opt, nlohmann::json& j) {
  ToolLink& link = ctx.link;
  if (!opt.identity) {
    ctx.err << "planter-can: lss inquire needs --identity VENDOR PRODUCT REVISION SERIAL\n";
    return kExitBadInput;
  }
  if (!select_by_identity(ctx, opt)) return kExitFailed;
  send_lss(link, cs::kInquireNodeId);
  const auto r = await_lss(link, cs::kInquireNodeId, opt.timeout_ns);
  send_lss(link, cs::kSwitchGlobal, 0);
  if (!r) {
    ctx.err << "planter-can: lss: the node did not answer the node-ID inquiry\n";
    return kExitFailed;
  }
  j["node_id"] = r->data[1];
  if (ctx.json) {
    ctx.out << j.dump(2) << "\n";
  } else {
    ctx.out << identity_text(*opt.identity) << ": node-ID " << unsigned{r->data[1]}
            << (r->data[1] == 0xFF ? " (unconfigured)" : "") << "\n";
  }
  return kExitOk;
}

// The action and the new ID checked before anything is sent: kExitOk when they may go on. Two
// nodes with one ID answer each other's SDOs and PDOs, so an ID already in use is refused.
int check_action(ToolContext& ctx, const LssOptions& opt) {
  if (opt.action != "fastscan" && opt.action != "assign") {
    ctx.err << "planter-can: lss: '" << opt.action
            << "' is not an LSS action (fastscan, assign, inquire)\n";
    return kExitBadInput;
  }
  if (opt.action != "assign") return kExitOk;
  if (opt.new_id < 1 || opt.new_id > 127) {
    ctx.err << "planter-can: lss assign: node-ID " << opt.new_id << " is out of range 1-127\n";
    return kExitBadInput;
  }
  SdoSession sdo(ctx.link, ctx.sdo_timeout_ns);
  if (sdo.read(static_cast<std::uint8_t>(opt.new_id), 0x1000, 0).ok()) {
    ctx.err << "planter-can: lss assign: node-ID " << opt.new_id
            << " is already used by a node on the bus (it answered a read of 0x1000); "
               "choose a free ID (planter-can scan lists them)\n";
    return kExitFailed;
  }
  return kExitOk;
}

// Assign: learn the old ID, configure, store, back to waiting; an unconfigured node takes the
// ID at once, a configured one on reset communication. Its boot-up frame confirms.
int assign(ToolContext& ctx, const LssOptions& opt, const Identity& id, nlohmann::json& j) {
  ToolLink& link = ctx.link;
  send_lss(link, cs::kInquireNodeId);
  const auto old = await_lss(link, cs::kInquireNodeId, opt.timeout_ns);
  const std::uint8_t old_id = old ? old->data[1] : canopen::kUnconfiguredNodeId;
  send_lss(link, cs::kConfigureNodeId, static_cast<std::uint32_t>(opt.new_id));
  const auto conf = await_lss(link, cs::kConfigureNodeId, opt.timeout_ns);
  if (!conf || conf->data[1] != 0) {
    send_lss(link, cs::kSwitchGlobal, 0);
    ctx.err << "planter-can: lss: the node " << (conf ? "refused" : "did not confirm")
            << " node-ID " << opt.new_id << "\n";
    return kExitFailed;
  }
  send_lss(link, cs::kStore);
  const auto stored = await_lss(link, cs::kStore, opt.timeout_ns);
  send_lss(link, cs::kSwitchGlobal, 0);
  if (old_id != canopen::kUnconfiguredNodeId) {
    link.send(canopen::nmt_frame(canopen::NmtCommand::kResetCommunication, old_id));
  }
  bool booted = false;
  hal::CanFrame f;
  const std::int64_t deadline = link.now_ns() + 1'000'000'000;
  while (!booted && link.receive_until(f, deadline)) {
    booted = f.is_standard_data() && f.cob_id() == canopen::kHeartbeatBase + opt.new_id &&
             f.dlc >= 1 && f.data[0] == 0;
  }
  j["old_node_id"] = old_id;
  j["new_node_id"] = opt.new_id;
  j["stored"] = stored && stored->data[1] == 0;
  j["boot_up_seen"] = booted;
  if (ctx.json) {
    ctx.out << j.dump(2) << "\n";
  } else {
    ctx.out << identity_text(id) << "\n  node-ID "
            << (old_id == 0xFF ? std::string("unconfigured") : std::to_string(old_id)) << " -> "
            << opt.new_id << (j["stored"].get<bool>() ? ", stored" : ", NOT stored")
            << (booted ? ", boot-up seen" : ", no boot-up seen within 1 s") << "\n";
  }
  return booted && j["stored"].get<bool>() ? kExitOk : kExitFailed;
}

}  // namespace

int run_lss(ToolContext& ctx, const LssOptions& opt) {
  ToolLink& link = ctx.link;
  nlohmann::json j{{"action", opt.action}};
  if (opt.action == "inquire") return inquire(ctx, opt, j);
  if (const int code = check_action(ctx, opt); code != kExitOk) return code;
  Identity id{};
  if (opt.identity) {
    if (!select_by_identity(ctx, opt)) return kExitFailed;
    id = *opt.identity;
  } else {
    int rounds = 0;
    const auto found = lss_fastscan(link, opt.timeout_ns, rounds);
    if (!found) {
      if (ctx.json) {
        j["found"] = false;
        ctx.out << j.dump(2) << "\n";
      } else {
        ctx.out << "no unconfigured node answered the fastscan\n";
      }
      return opt.action == "fastscan" ? kExitOk : kExitFailed;
    }
    id = *found;
  }
  j["found"] = true;
  j["identity"] = {
      {"vendor_id", id[0]}, {"product_code", id[1]}, {"revision", id[2]}, {"serial", id[3]}};
  if (opt.action == "assign") return assign(ctx, opt, id, j);
  send_lss(link, cs::kSwitchGlobal, 0);  // fastscan: back to waiting, unchanged
  if (ctx.json) {
    ctx.out << j.dump(2) << "\n";
  } else {
    ctx.out << "unconfigured node: " << identity_text(id) << "\n";
  }
  return kExitOk;
}

}  // namespace planter::cantool
