#pragma once
// The control core: from the process image in, a command out. It runs the supervisor and the
// three loops (sigma, clamp force, furrow depth) and knows nothing of CANopen, counts or lines:
// the I/O layer (firmware/io) turns the bus into a MachineState and a MachineCommand into frames.
// It owns no thread and no clock: time is passed in.
#include <cstdint>

#include "firmware/control/clamp_force_loop.h"
#include "firmware/control/furrow_depth_loop.h"
#include "firmware/control/sigma_loop.h"
#include "firmware/controller/controller_config.h"
#include "firmware/controller/operator_command.h"
#include "firmware/io/process_image.h"
#include "firmware/sensing/ground_fusion.h"
#include "firmware/sensing/load_cell_zero.h"
#include "firmware/sensing/planting_monitor.h"
#include "firmware/supervisor/link_recovery.h"
#include "firmware/supervisor/loop_alarms.h"
#include "firmware/supervisor/supervisor.h"

namespace planter {

class Controller {
 public:
  explicit Controller(const ControllerConfig& config);

  // One control period. `dt_ns` is the time since the previous tick.
  const MachineCommand& update(const MachineState& in, std::int64_t now_ns, std::int64_t dt_ns);

  // An operator's command, checked against the supervisor and the set-point rules
  // (setpoint_rules.h) and taken on the next update when accepted. No allocation.
  CommandOutcome command(const OperatorCommand& command);
  // The commissioning gate: while closed, an operator's run is refused.
  void set_run_gate(bool open) { run_gate_open_ = open; }

  // The daemon's own requests (its --run, signals and link recovery); taken on the next update.
  void request_run() { run_requested_ = true; }
  void request_stop() { stop_requested_ = true; }
  void request_fault_reset() { reset_requested_ = true; }

  // Stems whose wall the clamp loop saw give way since start.
  [[nodiscard]] long damage_seen() const { return clamp_loop_.stem().collapses(); }
  [[nodiscard]] SupervisorState state() const { return supervisor_.state(); }
  [[nodiscard]] std::uint32_t faults() const { return supervisor_.latched_faults(); }
  // Latched faults and those seen in the last update.
  [[nodiscard]] std::uint32_t faults_seen() const { return faults_seen_; }
  [[nodiscard]] std::uint32_t overruns() const { return overruns_; }
  [[nodiscard]] const PlantingFigures& planting() const { return monitor_.figures(); }
  // warning:: bits that hold now (they never stop the machine).
  [[nodiscard]] std::uint32_t warnings() const { return warnings_; }
  // Fault resets the link recovery has requested.
  [[nodiscard]] std::uint32_t link_resets() const { return link_recovery_.resets(); }
  // The load cell's zero taken while the lips were open (load_cell_zero.h).
  [[nodiscard]] double load_cell_offset_N() const { return load_cell_zero_.offset_N(); }
  // The ground as the sigma loop sees it: distance, speed, the slip and the GNSS fix's use.
  [[nodiscard]] const GroundFusion& ground() const { return ground_; }

 private:
  std::uint32_t check_faults(const MachineState& in, std::int64_t dt_ns);
  void decide_outputs(const MachineState& in, SupervisorState state, double dt_s);

  ControllerConfig cfg_;
  GroundFusion ground_;
  SigmaLoop sigma_loop_;
  ClampForceLoop clamp_loop_;
  FurrowDepthLoop depth_loop_;
  Supervisor supervisor_;
  LinkRecovery link_recovery_;
  PlantingMonitor monitor_;
  LoopAlarms alarms_;
  LoadCellZero load_cell_zero_;
  MachineCommand command_;
  std::uint32_t warnings_ = 0;

  bool run_gate_open_ = true;
  bool estop_held_ = false;  // at the last update
  bool run_requested_ = false;
  bool stop_requested_ = false;
  bool reset_requested_ = false;
  std::uint32_t consecutive_overruns_ = 0;
  std::uint32_t overruns_ = 0;
  std::uint32_t faults_seen_ = 0;
  std::int64_t disc_implausible_ns_ = 0;  // how long the disc has turned against the ground
  SupervisorState previous_state_ = SupervisorState::kBoot;
  std::int64_t running_for_ns_ = 0;
  bool zeroing_ = false;  // the lips held open for the load cell's zero
};

}  // namespace planter
