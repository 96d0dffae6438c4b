#include "apps/planter-can/cmd_configure.h"

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>

#include "apps/planter-can/sdo_session.h"
#include "firmware/canopen/nmt.h"
#include "firmware/io/node_config_script.h"

namespace planter::cantool {
namespace {

constexpr std::uint32_t kSaveSignature = 0x65766173;  // "save"

std::string step_line(std::uint8_t node, const ConfigStep& s) {
  char b[96];
  const char* type = s.size == 1 ? "u8" : s.size == 2 ? "u16" : "x32";
  if (s.write) {
    if (s.size == 4) {
      std::snprintf(b, sizeof b, "%u w 0x%04X %u %s 0x%08X", node, s.index, s.sub, type, s.value);
    } else {
      std::snprintf(b, sizeof b, "%u w 0x%04X %u %s %u", node, s.index, s.sub, type, s.value);
    }
  } else {
    std::snprintf(b, sizeof b, "%u r 0x%04X %u %s", node, s.index, s.sub, type);
  }
  return b;
}

struct NodeOutcome {
  std::string role;
  std::uint8_t id = 0;
  int writes = 0;
  int verified = 0;
  bool stored = false;
  std::string error;  // empty when all went well
};

NodeOutcome configure_node(ToolContext& ctx, const NodeConfig& n, const ConfigureOptions& opt) {
  NodeOutcome out;
  out.role = node_role_name(n.role);
  out.id = n.node_id;
  NodeConfigScript script;
  build_node_config_script(n, ctx.board->controller.can.heartbeat_producer_ms, script);
  SdoSession sdo(ctx.link, ctx.sdo_timeout_ns);
  // PDO maps may only change outside operational: put the node in pre-operational first.
  ctx.link.send(canopen::nmt_frame(canopen::NmtCommand::kPreOperational, n.node_id));
  std::map<std::pair<std::uint16_t, std::uint8_t>, const ConfigStep*> final_values;
  for (std::size_t i = 0; i < script.count; ++i) {
    const ConfigStep& s = script.steps[i];
    SdoResult r = s.write ? sdo.write_u32(n.node_id, s.index, s.sub, s.value, s.size)
                          : sdo.read(n.node_id, s.index, s.sub);
    char b[192];
    if (!r.ok()) {
      std::snprintf(b, sizeof b, "step %zu (%s): %s [boot error %c]", i + 1,
                    step_line(n.node_id, s).c_str(),
                    r.error_text(n.node_id, ctx.sdo_timeout_ns).c_str(), s.error);
      out.error = b;
      return out;
    }
    if (!s.write && (static_cast<std::uint32_t>(r.value()) & s.check_mask) != s.value) {
      std::snprintf(b, sizeof b,
                    "step %zu: %04X:%02X reads 0x%08X, the board expects 0x%08X [boot error %c]",
                    i + 1, s.index, s.sub, static_cast<std::uint32_t>(r.value()) & s.check_mask,
                    s.value, s.error);
      out.error = b;
      return out;
    }
    if (s.write) {
      ++out.writes;
      final_values[{s.index, s.sub}] = &s;
    }
  }
  for (const auto& [key, s] : final_values) {
    const SdoResult r = sdo.read(n.node_id, key.first, key.second);
    const std::uint32_t mask = s->size >= 4 ? 0xFFFFFFFFu : (1u << (8 * s->size)) - 1u;
    if (!r.ok() || (static_cast<std::uint32_t>(r.value()) & mask) != s->value) {
      char b[200];
      if (r.ok()) {
        std::snprintf(b, sizeof b, "read-back of %04X:%02X: 0x%08X, written 0x%08X", key.first,
                      key.second, static_cast<std::uint32_t>(r.value()) & mask, s->value);
      } else {
        std::snprintf(b, sizeof b, "read-back of %04X:%02X: %s", key.first, key.second,
                      r.error_text(n.node_id, ctx.sdo_timeout_ns).c_str());
      }
      out.error = b;
      return out;
    }
    ++out.verified;
  }
  if (opt.store) {
    const SdoResult r = sdo.write_u32(n.node_id, 0x1010, 1, kSaveSignature, 4);
    if (!r.ok()) {
      out.error = "store (0x1010:1 = \"save\"): " + r.error_text(n.node_id, ctx.sdo_timeout_ns);
      return out;
    }
    out.stored = true;
  }
  return out;
}

}  // namespace

int run_configure(ToolContext& ctx, const ConfigureOptions& opt) {
  if (ctx.board == nullptr) {
    ctx.err << "planter-can: configure needs --board (the node configuration comes from it)\n";
    return kExitBadInput;
  }
  std::vector<const NodeConfig*> nodes;
  for (const auto& n : ctx.board->controller.nodes) {
    if (opt.node.empty() || resolve_node(ctx, opt.node) == n.node_id) nodes.push_back(&n);
  }
  if (nodes.empty()) {
    ctx.err << "planter-can: configure: '" << opt.node << "' is not a node of " << ctx.board->file
            << "\n";
    return kExitBadInput;
  }
  if (opt.dry_run) {
    nlohmann::json j = nlohmann::json::array();
    for (const NodeConfig* n : nodes) {
      NodeConfigScript script;
      build_node_config_script(*n, ctx.board->controller.can.heartbeat_producer_ms, script);
      if (!ctx.json)
        ctx.out << "# " << node_role_name(n->role) << " (node " << unsigned{n->node_id} << ")\n";
      for (std::size_t i = 0; i < script.count; ++i) {
        const std::string line = step_line(n->node_id, script.steps[i]);
        if (ctx.json) {
          j.push_back({{"node", n->node_id}, {"role", node_role_name(n->role)}, {"line", line}});
        } else {
          ctx.out << line << "\n";
        }
      }
      if (opt.store) {
        char b[64];
        std::snprintf(b, sizeof b, "%u w 0x1010 1 x32 0x%08X", n->node_id, kSaveSignature);
        if (ctx.json) {
          j.push_back({{"node", n->node_id}, {"role", node_role_name(n->role)}, {"line", b}});
        } else {
          ctx.out << b << "\n";
        }
      }
    }
    if (ctx.json) ctx.out << j.dump(2) << "\n";
    return kExitOk;
  }
  Progress progress(ctx.err, ctx.progress);
  int exit_code = kExitOk;
  nlohmann::json j = nlohmann::json::array();
  for (const NodeConfig* n : nodes) {
    progress.update(std::string("configuring ") + node_role_name(n->role));
    const NodeOutcome o = configure_node(ctx, *n, opt);
    if (!o.error.empty()) exit_code = kExitFailed;
    j.push_back({{"node", o.id},
                 {"role", o.role},
                 {"writes", o.writes},
                 {"verified", o.verified},
                 {"stored", o.stored},
                 {"ok", o.error.empty()},
                 {"error", o.error}});
    if (!ctx.json) {
      char line[320];
      if (o.error.empty()) {
        std::snprintf(line, sizeof line, "%-16s node %-3u %3d writes, %3d read back ok, %s\n",
                      o.role.c_str(), o.id, o.writes, o.verified,
                      o.stored ? "stored" : "not stored");
      } else {
        std::snprintf(line, sizeof line, "%-16s node %-3u FAILED: %s\n", o.role.c_str(), o.id,
                      o.error.c_str());
      }
      progress.done();
      ctx.out << line;
    }
  }
  progress.done();
  if (ctx.json) ctx.out << j.dump(2) << "\n";
  return exit_code;
}

}  // namespace planter::cantool
