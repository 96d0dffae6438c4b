#pragma once
// `scan`: listen, then probe 0x1000 on node-IDs 1-127 (paced), then read each found node's
// identity. Under 2 s on an idle bus.
#include <cstdint>
#include <string>
#include <vector>

#include "apps/planter-can/bus_watch.h"
#include "apps/planter-can/tool_context.h"

namespace planter::cantool {

struct ScanOptions {
  std::int64_t listen_ns = 300'000'000;
  bool probe = true;
  std::uint8_t first_id = 1;
  std::uint8_t last_id = 127;
};

struct ScannedNode {
  std::uint8_t id = 0;
  bool answered_sdo = false;
  std::uint32_t device_type = 0;
  std::uint32_t vendor = 0, product = 0, revision = 0, serial = 0;
  std::string device_name;
  std::uint8_t state = 0xFF;  // from heartbeats; 0xFF = none heard
  std::string role;           // from the board
};

struct ScanResult {
  std::vector<ScannedNode> nodes;
  std::int64_t duration_ns = 0;
  std::uint32_t probes_sent = 0;
  BusWatch watch;
};

ScanResult scan_bus(ToolContext& ctx, const ScanOptions& options);
int run_scan(ToolContext& ctx, const ScanOptions& options);

}  // namespace planter::cantool
