#include "apps/planter-can/cmd_info.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <ostream>

#include "apps/planter-can/object_names.h"
#include "apps/planter-can/sdo_session.h"
#include "firmware/canopen/pdo.h"

namespace planter::cantool {
namespace {

std::string hex32(std::uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08X", v);
  return b;
}

// Reads one node's objects over SDO: a string, or a value with whether it was read.
class NodeReader {
 public:
  NodeReader(SdoSession& sdo, std::uint8_t id, std::int64_t timeout_ns)
      : sdo_(sdo), id_(id), timeout_ns_(timeout_ns) {}
  std::string text(std::uint16_t index) {
    const SdoResult r = sdo_.read(id_, index, 0);
    return r.ok() ? std::string(r.data.begin(), r.data.end())
                  : "(" + r.error_text(id_, timeout_ns_) + ")";
  }
  std::uint32_t u32(std::uint16_t index, std::uint8_t sub, bool& ok) {
    const SdoResult r = sdo_.read(id_, index, sub);
    ok = r.ok();
    return static_cast<std::uint32_t>(r.value());
  }

 private:
  SdoSession& sdo_;
  std::uint8_t id_;
  std::int64_t timeout_ns_;
};

constexpr const char* kIdentityNames[] = {"vendor_id", "product_code", "revision", "serial"};

// The identity object (0x1018), the error register and history (0x1001, 0x1003) and the
// heartbeat (0x1017).
void read_identity_and_errors(NodeReader& node, nlohmann::json& j) {
  bool ok = false;
  for (std::uint8_t s = 1; s <= 4; ++s) {
    const std::uint32_t v = node.u32(0x1018, s, ok);
    j["identity"][kIdentityNames[s - 1]] = ok ? hex32(v) : "-";
  }
  const std::uint32_t err_reg = node.u32(0x1001, 0, ok);
  j["error_register"] = ok ? hex32(err_reg) : "-";
  const std::uint32_t history = node.u32(0x1003, 0, ok);
  j["error_history"] = nlohmann::json::array();
  if (ok) {
    for (std::uint8_t s = 1; s <= history && s <= 16; ++s) {
      bool ok2 = false;
      const std::uint32_t code = node.u32(0x1003, s, ok2);
      if (ok2) {
        j["error_history"].push_back(
            {{"code", hex32(code)}, {"meaning", emcy_code_text(static_cast<std::uint16_t>(code))}});
      }
    }
  }
  const std::uint32_t hb = node.u32(0x1017, 0, ok);
  j["heartbeat_ms"] = ok ? nlohmann::json(hb) : nlohmann::json("-");
}

// Each PDO the node has (TPDO then RPDO 1-4): its COB-ID, transmission type and mapping.
nlohmann::json read_pdos(NodeReader& node) {
  nlohmann::json pdos = nlohmann::json::array();
  bool ok = false;
  for (int dir = 0; dir < 2; ++dir) {
    for (std::uint16_t k = 0; k < 4; ++k) {
      const auto comm = static_cast<std::uint16_t>((dir == 0 ? 0x1800 : 0x1400) + k);
      const auto map = static_cast<std::uint16_t>((dir == 0 ? 0x1A00 : 0x1600) + k);
      const std::uint32_t cob = node.u32(comm, 1, ok);
      if (!ok) continue;
      bool ok_type = false;
      const std::uint32_t transmission = node.u32(comm, 2, ok_type);
      nlohmann::json p{{"pdo", std::string(dir == 0 ? "TPDO" : "RPDO") + std::to_string(k + 1)},
                       {"cob_id", hex32(cob & 0x7FF)},
                       {"valid", (cob & 0x80000000u) == 0},
                       {"transmission", transmission}};
      const std::uint32_t count = node.u32(map, 0, ok);
      p["mapping"] = nlohmann::json::array();
      for (std::uint8_t s = 1; ok && s <= count && s <= 8; ++s) {
        bool ok2 = false;
        const auto e = canopen::PdoEntry::from_mapping_value(node.u32(map, s, ok2));
        if (!ok2) break;
        char buf[64];
        char entry[96];
        std::snprintf(entry, sizeof entry, "%04X:%02X/%u %s", e.index, e.sub, e.bits,
                      std::string(object_label(e.index, e.sub, buf, sizeof buf)).c_str());
        p["mapping"].push_back(entry);
      }
      pdos.push_back(p);
    }
  }
  return pdos;
}

// The node's figures as aligned lines, from the JSON that --json prints.
void print_info(std::ostream& out, std::uint8_t id, const nlohmann::json& j) {
  auto row = [&](const char* k, const std::string& v) {
    char line[256];
    std::snprintf(line, sizeof line, "%-18s %s\n", k, v.c_str());
    out << line;
  };
  row("node",
      std::to_string(id) +
          (j["role"].get<std::string>().empty() ? "" : " (" + j["role"].get<std::string>() + ")"));
  row("device type", j["device_type"].get<std::string>() + "  " + j["profile"].get<std::string>());
  row("device name", j["device_name"].get<std::string>());
  row("hardware version", j["hardware_version"].get<std::string>());
  row("software version", j["software_version"].get<std::string>());
  for (const char* k : kIdentityNames) row(k, j["identity"][k].get<std::string>());
  row("error register", j["error_register"].get<std::string>());
  if (j["error_history"].empty()) row("error history", "empty");
  for (const auto& e : j["error_history"])
    row("error history", e["code"].get<std::string>() + "  " + e["meaning"].get<std::string>());
  row("heartbeat",
      j["heartbeat_ms"].is_number() ? std::to_string(j["heartbeat_ms"].get<int>()) + " ms" : "-");
  for (const auto& p : j["pdos"]) {
    std::string v = p["cob_id"].get<std::string>() + (p["valid"].get<bool>() ? "" : " (invalid)") +
                    " type " + std::to_string(p["transmission"].get<int>());
    for (const auto& m : p["mapping"]) v += "\n" + std::string(19, ' ') + m.get<std::string>();
    row(p["pdo"].get<std::string>().c_str(), v);
  }
}

}  // namespace

int run_info(ToolContext& ctx, const std::string& node_text) {
  const std::uint8_t id = resolve_node(ctx, node_text);
  if (id == 0) {
    ctx.err << "planter-can: info: '" << node_text
            << "' is not a node-ID (1-127) or a node of the board\n";
    return kExitBadInput;
  }
  SdoSession sdo(ctx.link, ctx.sdo_timeout_ns);
  const SdoResult type = sdo.read(id, 0x1000, 0);
  if (!type.ok()) {
    ctx.err << "planter-can: info: node " << unsigned{id} << ": "
            << type.error_text(id, ctx.sdo_timeout_ns) << "\n";
    return kExitFailed;
  }
  NodeReader node(sdo, id, ctx.sdo_timeout_ns);
  nlohmann::json j;
  j["node"] = id;
  j["role"] = node_role_of(ctx, id);
  const auto device_type = static_cast<std::uint32_t>(type.value());
  j["device_type"] = hex32(device_type);
  j["profile"] = device_profile_text(device_type);
  j["device_name"] = node.text(0x1008);
  j["hardware_version"] = node.text(0x1009);
  j["software_version"] = node.text(0x100A);
  read_identity_and_errors(node, j);
  j["pdos"] = read_pdos(node);
  if (ctx.json)
    ctx.out << j.dump(2) << "\n";
  else
    print_info(ctx.out, id, j);
  return kExitOk;
}

}  // namespace planter::cantool
