#pragma once
// Plain data the machine is built from: the I/O layer's part and each loop's own config,
// declared beside what it configures. Filled by the board-file loader (config/) at init.
#include <array>
#include <cstdint>

#include "firmware/control/clamp_force_loop.h"
#include "firmware/control/furrow_depth_loop.h"
#include "firmware/control/sigma_loop.h"
#include "firmware/io/io_config.h"
#include "firmware/sensing/ground_fusion.h"
#include "firmware/sensing/load_cell_zero.h"
#include "firmware/sensing/planting_monitor.h"
#include "firmware/supervisor/link_recovery.h"
#include "firmware/supervisor/loop_alarms.h"
#include "firmware/supervisor/supervisor.h"

namespace planter {

struct ControllerConfig {
  CanConfig can;
  std::array<NodeConfig, kNodeCount> nodes{};
  EncoderConfig encoder;
  GroundFusionConfig ground;  // the wheel, and GNSS where the board has a receiver
  SigmaLoopConfig sigma;
  ClampLoopConfig clamp;
  DepthLoopConfig depth;
  SupervisorConfig supervisor;
  LinkRecoveryConfig link_recovery;  // off unless the board or planterd turns it on
  PlantingMonitorConfig monitor;
  LoopAlarmConfig alarms;
  LoadCellZeroConfig load_cell_zero;
  bool estop_active_low = true;

  [[nodiscard]] const NodeConfig& node(NodeRole r) const {
    return nodes[static_cast<std::size_t>(r)];
  }
};

}  // namespace planter
