#pragma once
// What every command gets: the bus, the board (when one was given), how to print, and the
// SDO timeout. Commands return the process exit code: 0 ok, 1 a check or transfer failed,
// 2 bad input.
#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <string>

#include "apps/planter-can/tool_link.h"
#include "config/board_config.h"

namespace planter::cantool {

// Shows progress on stderr for anything that takes longer than a second (wall time).
class Progress {
 public:
  explicit Progress(std::ostream& err, bool enabled) : err_(err), enabled_(enabled) {}
  void update(const std::string& what);
  void done();

 private:
  std::ostream& err_;
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_ = start_;
};

struct ToolContext {
  ToolLink& link;
  const config::BoardConfig* board = nullptr;  // null without --board
  bool json = false;
  std::ostream& out;
  std::ostream& err;
  std::int64_t sdo_timeout_ns = 100'000'000;
  bool progress = true;
};

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitBadInput = 2;

// Node-ID of a node named by number or by board role ("depth_actuator"); 0 when unknown.
std::uint8_t resolve_node(const ToolContext& ctx, const std::string& text);
// The board's role name of a node-ID, or "".
std::string node_role_of(const ToolContext& ctx, std::uint8_t node_id);

}  // namespace planter::cantool
