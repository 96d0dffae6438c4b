#pragma once
// The SDO steps that bring one node to the board's configuration, in the order CiA 301 and
// CiA 302-2 ask for: identity checks, drive mode, SYNC consumer, PDOs (invalidate, clear, map,
// count, validate), heartbeat last. The controller's boot and planter-can's `configure` both run
// it.
#include <array>
#include <cstddef>
#include <cstdint>

#include "firmware/io/io_config.h"

namespace planter {

struct ConfigStep {
  bool write = false;
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint8_t size = 4;
  std::uint32_t value = 0;
  std::uint32_t check_mask = 0;  // reads: (read value & mask) must equal `value`
  char error = 0;                // CiA 302-2 boot error letter when the step fails
};

struct NodeConfigScript {
  static constexpr std::size_t kMaxSteps = 96;
  std::array<ConfigStep, kMaxSteps> steps{};
  std::size_t count = 0;
  bool overflow = false;  // more steps than fit: the script is incomplete

  void add(const ConfigStep& step);
};

// No allocation: the script lives in the caller's storage.
void build_node_config_script(const NodeConfig& node, std::uint16_t heartbeat_ms,
                              NodeConfigScript& out);

}  // namespace planter
