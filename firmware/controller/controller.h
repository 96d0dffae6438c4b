#pragma once
// The machine controller: one tick reads the bus and the lines, runs the supervisor and the
// three loops, and writes the drives. It owns no thread and no clock: time is passed in.
#include <array>
#include <cstdint>

#include "firmware/canopen/cob_id.h"
#include "firmware/control/clamp_force_loop.h"
#include "firmware/control/furrow_depth_loop.h"
#include "firmware/control/sigma_loop.h"
#include "firmware/controller/controller_config.h"
#include "firmware/controller/node_link.h"
#include "firmware/controller/telemetry.h"
#include "firmware/sensing/ground_speed_estimator.h"
#include "firmware/sensing/quadrature_decoder.h"
#include "firmware/supervisor/supervisor.h"
#include "planter/hal/controller_hal.h"

namespace planter {

class Controller {
 public:
  Controller(const ControllerConfig& config, hal::ControllerHal& hal);

  // One control period. `dt_ns` is the time since the previous tick.
  void tick(std::int64_t now_ns, std::int64_t dt_ns);

  // Operator commands; taken on the next tick.
  void request_run() { run_requested_ = true; }
  void request_stop() { stop_requested_ = true; }
  void request_fault_reset() { reset_requested_ = true; }

  [[nodiscard]] const Telemetry& telemetry() const { return telemetry_; }
  [[nodiscard]] SupervisorState state() const { return supervisor_.state(); }
  [[nodiscard]] const NodeLink& node(NodeRole role) const {
    return links_[static_cast<std::size_t>(role)];
  }
  [[nodiscard]] std::uint32_t faults() const { return supervisor_.latched_faults(); }

 private:
  void mark(hal::TickPhase phase) {
    if (hal_.tick_probe != nullptr) hal_.tick_probe->phase_done(phase);
  }
  NodeLink& link(NodeRole role) { return links_[static_cast<std::size_t>(role)]; }
  void read_bus(std::int64_t now_ns);
  void read_encoder(std::int64_t now_ns);
  void read_process_values();
  std::uint32_t check_faults(std::int64_t now_ns, std::int64_t dt_ns);
  void run_commissioning(std::int64_t now_ns);
  void write_outputs(double dt_s);
  void send_nmt(canopen::NmtCommand command, std::uint8_t node_id);
  void send_sync();

  ControllerConfig cfg_;
  hal::ControllerHal& hal_;
  std::array<NodeLink, kNodeCount> links_;
  QuadratureDecoder decoder_;
  GroundSpeedEstimator ground_speed_;
  SigmaLoop sigma_loop_;
  ClampForceLoop clamp_loop_;
  FurrowDepthLoop depth_loop_;
  Supervisor supervisor_;
  Telemetry telemetry_;

  // Slots of the process values used every tick (found once at init).
  int disc_velocity_slot_, disc_position_slot_, disc_torque_slot_, disc_target_slot_;
  int roller_position_slot_;
  int depth_position_slot_, depth_torque_slot_;
  int force_slot_;

  bool run_requested_ = false;
  bool stop_requested_ = false;
  bool reset_requested_ = false;
  bool commissioning_started_ = false;
  bool nodes_started_ = false;
  std::int64_t commissioning_start_ns_ = 0;
  std::uint32_t consecutive_overruns_ = 0;
  std::int64_t disc_implausible_ns_ = 0;  // how long the disc has turned against the ground
  SupervisorState previous_state_ = SupervisorState::kBoot;
  std::array<std::uint32_t, kNodeCount> boot_ups_seen_{};
};

}  // namespace planter
