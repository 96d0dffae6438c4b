#pragma once
// One control tick, read -> update -> write: the I/O layer reads the machine into the process
// image, the controller decides a command, the I/O layer writes it to the bus. This is the
// firmware's whole entry point; planterd, the lockstep runner and planter-can's simulated
// controller each call tick() once a period.
#include <cstdint>

#include "firmware/controller/controller.h"
#include "firmware/controller/controller_config.h"
#include "firmware/controller/telemetry.h"
#include "firmware/io/machine_io.h"
#include "planter/hal/controller_hal.h"

namespace planter {

// The I/O layer's share of the machine's configuration.
MachineIoConfig machine_io_config(const ControllerConfig& config);

class ControlCycle {
 public:
  ControlCycle(const ControllerConfig& config, hal::ControllerHal& hal);

  // One control period at `now_ns`; `dt_ns` is the time since the previous tick.
  void tick(std::int64_t now_ns, std::int64_t dt_ns);

  CommandOutcome command(const OperatorCommand& c) { return controller_.command(c); }
  void set_run_gate(bool open) { controller_.set_run_gate(open); }
  void request_run() { controller_.request_run(); }
  void request_stop() { controller_.request_stop(); }
  void request_fault_reset() { controller_.request_fault_reset(); }

  [[nodiscard]] const Telemetry& telemetry() const { return telemetry_; }
  [[nodiscard]] SupervisorState state() const { return controller_.state(); }
  [[nodiscard]] std::uint32_t faults() const { return controller_.faults(); }
  [[nodiscard]] std::uint32_t link_resets() const { return controller_.link_resets(); }
  [[nodiscard]] const NodeLink& node(NodeRole role) const { return io_.node(role); }

 private:
  void mark(hal::TickPhase phase) {
    if (probe_ != nullptr) probe_->phase_done(phase);
  }

  MachineIo io_;
  Controller controller_;
  hal::TickProbe* probe_;
  Telemetry telemetry_;
};

}  // namespace planter
