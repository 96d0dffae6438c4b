#include "apps/planter-can/tool_context.h"

#include <ostream>

#include "apps/planter-can/value_codec.h"

namespace planter::cantool {

void Progress::update(const std::string& what) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < std::chrono::seconds(1) || now - last_ < std::chrono::milliseconds(200))
    return;
  last_ = now;
  err_ << "\r" << what << "\x1b[K" << std::flush;
  shown_ = true;
}

void Progress::done() {
  if (shown_) err_ << "\r\x1b[K" << std::flush;
  shown_ = false;
}

std::uint8_t resolve_node(const ToolContext& ctx, const std::string& text) {
  if (const auto v = parse_integer(text); v && *v >= 1 && *v <= 127)
    return static_cast<std::uint8_t>(*v);
  if (ctx.board != nullptr) {
    for (const auto& n : ctx.board->controller.nodes) {
      if (text == node_role_name(n.role)) return n.node_id;
    }
  }
  return 0;
}

std::string node_role_of(const ToolContext& ctx, std::uint8_t node_id) {
  if (ctx.board == nullptr) return "";
  for (const auto& n : ctx.board->controller.nodes) {
    if (n.node_id == node_id) return node_role_name(n.role);
  }
  return "";
}

}  // namespace planter::cantool
