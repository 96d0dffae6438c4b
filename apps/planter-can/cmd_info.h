#pragma once
// `info NODE`: what a node says about itself, decoded.
#include <string>

#include "apps/planter-can/tool_context.h"

namespace planter::cantool {
int run_info(ToolContext& ctx, const std::string& node);
}  // namespace planter::cantool
