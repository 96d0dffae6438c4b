#pragma once
// `configure`: brings the board's nodes to its configuration with the same SDO script the
// controller runs at boot (identity checks, drive mode, PDO maps in CiA 301 order, heartbeat),
// then reads every object back, then stores it (0x1010:1 = "save"). --dry-run prints the
// script as CiA 309-3 lines, which `sdo -f` accepts.
#include <string>

#include "apps/planter-can/tool_context.h"

namespace planter::cantool {

struct ConfigureOptions {
  std::string node;  // empty = every node of the board
  bool dry_run = false;
  bool store = true;
};

int run_configure(ToolContext& ctx, const ConfigureOptions& options);

}  // namespace planter::cantool
