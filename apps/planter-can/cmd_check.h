#pragma once
// `check`: the commissioning checklist. Every item passes or fails with the figure behind it;
// the exit code is 1 when any item fails.
#include "apps/planter-can/tool_context.h"

namespace planter::cantool {

struct CheckOptions {
  std::int64_t listen_ns = 2'000'000'000;  // how long heartbeats and PDOs are watched
  double max_bus_load_pct = 50.0;
  bool encoder = true;  // check the encoder direction (needs GPIO access and a push)
  double ready_after_s = -1.0;
  std::string mark_commissioned;  // stamp file written when every item passed
};

int run_check(ToolContext& ctx, const CheckOptions& options, std::istream& in);

}  // namespace planter::cantool
