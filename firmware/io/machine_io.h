#pragma once
// The I/O layer between the bus and the control core, in the manner of ros2_control's
// read/write: read() turns bus frames, encoder edges and lines into a MachineState in SI units;
// write() turns a MachineCommand into RPDOs and SYNC, and boots the nodes while asked to. It owns
// the CANopen node links; which object carries which signal, and its scale, comes from
// signal_table.h alone.
#include <array>
#include <cstdint>

#include "firmware/io/io_config.h"
#include "firmware/io/node_link.h"
#include "firmware/io/process_image.h"
#include "firmware/io/signal_table.h"
#include "firmware/sensing/ground_speed_estimator.h"
#include "firmware/sensing/quadrature_decoder.h"
#include "firmware/supervisor/supervisor.h"
#include "planter/hal/controller_hal.h"

namespace planter {

struct MachineIoConfig {
  CanConfig can;
  std::array<NodeConfig, kNodeCount> nodes{};
  EncoderConfig encoder;
  std::int64_t pdo_stale_ns = 100'000'000;  // no fresh TPDO for this long: kPdoStale
  std::int64_t boot_timeout_ns = 5'000'000'000;
  // Photo-eye beam breaks closer than this to the last one are one seedling (leaves flicker);
  // the board's value comes from PlantingMonitorConfig.
  std::int64_t seedling_filter_ns = 0;
};

class MachineIo {
 public:
  MachineIo(const MachineIoConfig& config, hal::ControllerHal& hal);

  // Everything that arrived since the last tick, in SI units.
  const MachineState& read(std::int64_t now_ns);
  // Boots the nodes while `command.commissioning`, then sends the command's RPDOs and SYNC.
  void write(std::int64_t now_ns, const MachineCommand& command);

  [[nodiscard]] const MachineState& state() const { return state_; }
  [[nodiscard]] const NodeLink& node(NodeRole role) const {
    return links_[static_cast<std::size_t>(role)];
  }

 private:
  NodeLink& link(NodeRole role) { return links_[static_cast<std::size_t>(role)]; }
  void read_bus(std::int64_t now_ns);
  void read_encoder(std::int64_t now_ns);
  void read_process_values();
  std::uint32_t check_links(std::int64_t now_ns) const;
  void step_commissioning(std::int64_t now_ns);
  void send_sync();

  MachineIoConfig cfg_;
  hal::ControllerHal& hal_;
  std::array<NodeLink, kNodeCount> links_;
  QuadratureDecoder decoder_;
  GroundSpeedEstimator ground_speed_;
  MachineState state_;
  // Process-image slots of the bus signals, found once (kSignals order; -1 when not mapped).
  std::array<int, kSignals.size()> slots_{};

  std::int64_t last_seedling_ns_ = -1'000'000'000'000;
  bool commissioning_ = false;  // the last command asked for commissioning
  bool commissioning_started_ = false;
  std::int64_t commissioning_start_ns_ = 0;
  std::array<std::uint32_t, kNodeCount> boot_ups_seen_{};
};

}  // namespace planter
