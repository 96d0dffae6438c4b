#pragma once
// `lss`: node-ID assignment for nodes straight from the box (node-ID 0xFF) by fastscan, or
// for a known identity by switch-selective; `lss inquire` asks a selected node its ID.
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "apps/planter-can/tool_context.h"

namespace planter::cantool {

struct LssOptions {
  std::string action;                                    // fastscan | assign | inquire
  int new_id = 0;                                        // assign
  std::optional<std::array<std::uint32_t, 4>> identity;  // vendor, product, revision, serial
  std::int64_t timeout_ns = 20'000'000;                  // silence this long means "no"
};

// Fastscan: the identity of one unconfigured node, which is left in configuration state.
std::optional<std::array<std::uint32_t, 4>> lss_fastscan(ToolLink& link, std::int64_t timeout_ns,
                                                         int& rounds);
int run_lss(ToolContext& ctx, const LssOptions& options);

}  // namespace planter::cantool
