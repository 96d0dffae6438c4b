#include "apps/planter-can/cmd_sdo.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <sstream>
#include <vector>

#include "apps/planter-can/cmd_scan.h"
#include "apps/planter-can/object_names.h"
#include "apps/planter-can/sdo_session.h"
#include "config/config_error.h"
#include "config/input_file.h"
#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/nmt.h"

namespace planter::cantool {

bool read_batch_file(const std::string& path, std::vector<SdoLine>& lines, std::string& error) {
  std::istringstream in;
  try {
    in.str(config::read_input_file(path));  // no FIFO or directory; a BOM is skipped
  } catch (const config::ConfigError& e) {
    error = e.what();
    return false;
  }
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos || text[first] == '#') continue;
    lines.push_back({path + ":" + std::to_string(number), text});
  }
  return true;
}

std::string execute_cia309(ToolContext& ctx, const Cia309Command& cmd, bool& ok) {
  SdoSession sdo(ctx.link, ctx.sdo_timeout_ns);
  ok = true;
  if (cmd.kind == Cia309Command::Kind::kNmt) {
    ok = ctx.link.send(canopen::nmt_frame(cmd.nmt, cmd.node));
    return ok ? "OK" : "ERROR: the frame could not be sent (transmit queue full or bus-off)";
  }
  SdoResult res = cmd.kind == Cia309Command::Kind::kRead
                      ? sdo.read(cmd.node, cmd.index, cmd.sub)
                      : sdo.write(cmd.node, cmd.index, cmd.sub, cmd.value);
  if (!res.ok()) {
    ok = false;
    char buf[160];
    if (res.status == SdoResult::Status::kTimedOut) {
      std::snprintf(buf, sizeof buf, "ERROR: 0x%08X no answer from node %u in %lld ms",
                    res.abort_code, cmd.node,
                    static_cast<long long>(ctx.sdo_timeout_ns / 1'000'000));
    } else {
      std::snprintf(buf, sizeof buf, "ERROR: 0x%08X %s", res.abort_code,
                    canopen::abort_code_text(res.abort_code));
    }
    // An index typed as the object tables print it (1018) but without 0x was read as decimal.
    constexpr std::uint32_t kNoSuchObject = 0x06020000;
    if (res.abort_code == kNoSuchObject && cmd.index_decimal) {
      char hint[120];
      std::snprintf(hint, sizeof hint,
                    "; the index %u was read as decimal (0x%04X): write 0x%u for hexadecimal",
                    cmd.index, cmd.index, cmd.index);
      return std::string(buf) + hint;
    }
    return buf;
  }
  if (cmd.kind == Cia309Command::Kind::kWrite) return "OK";
  ValueType type;
  if (cmd.type) {
    type = *cmd.type;
  } else if (const ObjectInfo* o = find_object(cmd.index, cmd.sub)) {
    type = *parse_value_type(o->type);
  } else {
    // Unknown to the tables: hexadecimal of the size the node sent, or raw bytes.
    const std::size_t n = res.data.size();
    type = *parse_value_type(n == 1 || n == 2 || n == 4 || n == 8 ? "x" + std::to_string(8 * n)
                                                                  : std::string("os"));
  }
  // A fixed-size type must match what the node sent (issue 28, item 13: u8 on a 32-bit value
  // printed its low byte as if it were the value).
  const bool fixed_size = type.kind != ValueKind::kString && type.kind != ValueKind::kOctets;
  if (fixed_size && res.data.size() != type.bytes) {
    ok = false;
    return "ERROR: the object holds " + std::to_string(res.data.size()) + " bytes, not the " +
           std::to_string(type.bytes) + " of this type: read it as a " +
           std::to_string(8 * res.data.size()) + "-bit type (u" +
           std::to_string(8 * res.data.size()) + ", x" + std::to_string(8 * res.data.size()) +
           ", or os for raw bytes)";
  }
  return format_value(type, res.data);
}

int run_sdo(ToolContext& ctx, const std::vector<SdoLine>& lines) {
  // Parse everything first: a batch with a typo is not half applied.
  std::vector<Cia309Command> commands;
  for (const auto& l : lines) {
    Cia309Parse p = parse_cia309(l.text);
    if (const auto* e = std::get_if<Cia309Error>(&p)) {
      ctx.err << "planter-can: " << l.source << ": " << e->text() << "\n";
      return kExitBadInput;
    }
    commands.push_back(std::get<Cia309Command>(p));
  }
  int exit_code = kExitOk;
  nlohmann::json results = nlohmann::json::array();
  for (std::size_t i = 0; i < commands.size(); ++i) {
    const Cia309Command& c = commands[i];
    bool ok = false;
    const std::string reply = execute_cia309(ctx, c, ok);
    if (!ok) exit_code = kExitFailed;
    const std::string seq = c.sequence ? "[" + std::to_string(*c.sequence) + "] " : "";
    if (ctx.json) {
      nlohmann::json j{{"command", lines[i].text}, {"ok", ok}, {"reply", reply}};
      if (c.sequence) j["sequence"] = *c.sequence;
      results.push_back(j);
    } else {
      ctx.out << seq << reply << "\n";
    }
  }
  if (ctx.json) ctx.out << results.dump(2) << "\n";
  return exit_code;
}

int run_nmt(ToolContext& ctx, const std::string& command, const std::string& node_text) {
  struct Row {
    const char* word;
    canopen::NmtCommand cs;
    std::uint8_t expect;  // heartbeat state that confirms it; 0xFF = none
  };
  static constexpr Row kRows[] = {
      {"start", canopen::NmtCommand::kStart, 0x05},
      {"stop", canopen::NmtCommand::kStop, 0x04},
      {"preop", canopen::NmtCommand::kPreOperational, 0x7F},
      {"reset", canopen::NmtCommand::kResetNode, 0x00},
      {"reset-comm", canopen::NmtCommand::kResetCommunication, 0x00},
  };
  const Row* row = nullptr;
  for (const auto& r : kRows) {
    if (command == r.word) row = &r;
  }
  if (row == nullptr) {
    ctx.err << "planter-can: nmt: '" << command
            << "' is not an NMT command (start, stop, preop, reset, reset-comm)\n";
    return kExitBadInput;
  }
  std::uint8_t node = 0;
  if (node_text != "all" && node_text != "0") {
    node = resolve_node(ctx, node_text);
    if (node == 0) {
      ctx.err << "planter-can: nmt: '" << node_text
              << "' is not a node-ID (1-127), 'all' or a node of the board\n";
      return kExitBadInput;
    }
  }
  if (!ctx.link.send(canopen::nmt_frame(row->cs, node))) {
    ctx.err << "planter-can: nmt: the frame could not be sent (transmit queue full or bus-off)\n";
    return kExitFailed;
  }
  // Confirmation: the heartbeat (or boot-up) with the new state, within a second: of the node,
  // or for "all" of every node of the board (without a board, of every node that answers).
  std::set<int> expected;
  if (node != 0) {
    expected.insert(node);
  } else if (ctx.board != nullptr) {
    for (const NodeConfig& n : ctx.board->controller.nodes) expected.insert(n.node_id);
  }
  std::set<int> confirmed_ids;
  BusWatch watch;
  const std::int64_t t0 = ctx.link.now_ns();
  watch.start(t0);
  hal::CanFrame r;
  while ((expected.empty() || !std::includes(confirmed_ids.begin(), confirmed_ids.end(),
                                             expected.begin(), expected.end())) &&
         ctx.link.receive_until(r, t0 + 1'000'000'000)) {
    watch.on_frame(r, ctx.link.now_ns());
    if (!r.is_standard_data() || r.dlc < 1) continue;
    const int id = static_cast<int>(r.cob_id()) - static_cast<int>(canopen::kHeartbeatBase);
    if (id < 1 || id > 127 || (r.data[0] & 0x7F) != row->expect) continue;
    if (node == 0 || id == node) confirmed_ids.insert(id);
  }
  std::vector<int> missing;
  for (int id : expected)
    if (!confirmed_ids.count(id)) missing.push_back(id);
  const bool confirmed = expected.empty() ? !confirmed_ids.empty() : missing.empty();
  auto ids_text = [](const auto& ids) {
    std::string t;
    for (int id : ids) t += (t.empty() ? "" : " ") + std::to_string(id);
    return t;
  };
  const std::string who = node == 0 ? "all nodes" : "node " + std::to_string(node);
  if (ctx.json) {
    nlohmann::json j{{"command", command},
                     {"node", node},
                     {"sent", true},
                     {"confirmed", confirmed},
                     {"confirmed_nodes", confirmed_ids},
                     {"unconfirmed_nodes", missing}};
    ctx.out << j.dump(2) << "\n";
  } else if (confirmed) {
    ctx.out << command << " " << who << ": confirmed, heartbeat says "
            << nmt_state_name(row->expect)
            << (node == 0 ? " (nodes " + ids_text(confirmed_ids) + ")" : std::string()) << "\n";
  } else {
    ctx.err << "planter-can: nmt: " << command << " " << who << ": sent, not confirmed: no "
            << "heartbeat within 1 s says " << nmt_state_name(row->expect)
            << (missing.empty() ? std::string() : " from node(s) " + ids_text(missing))
            << " (no such node, or its heartbeat is off)\n";
  }
  // A node that never answers is a timeout, exit 1 (docs/planter-can.md).
  return confirmed ? kExitOk : kExitFailed;
}

}  // namespace planter::cantool
