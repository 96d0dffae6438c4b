#include "firmware/controller/control_cycle.h"

namespace planter {

MachineIoConfig machine_io_config(const ControllerConfig& c) {
  MachineIoConfig io;
  io.can = c.can;
  io.nodes = c.nodes;
  io.encoder = c.encoder;
  io.pdo_stale_ns = c.supervisor.pdo_stale_ns;
  io.boot_timeout_ns = c.supervisor.boot_timeout_ns;
  io.seedling_filter_ns = c.monitor.sensor_filter_ns;
  return io;
}

ControlCycle::ControlCycle(const ControllerConfig& config, hal::ControllerHal& hal)
    : io_(machine_io_config(config), hal), controller_(config), probe_(hal.tick_probe) {}

void ControlCycle::tick(std::int64_t now_ns, std::int64_t dt_ns) {
  const MachineState& state = io_.read(now_ns);
  mark(hal::TickPhase::kReceive);
  const MachineCommand& command = controller_.update(state, now_ns, dt_ns);
  mark(hal::TickPhase::kControl);
  io_.write(now_ns, command);
  mark(hal::TickPhase::kTransmit);

  static_cast<MachineState&>(telemetry_) = io_.state();
  static_cast<MachineCommand&>(telemetry_) = command;
  telemetry_.time_ns = now_ns;
  telemetry_.state = controller_.state();
  telemetry_.faults = controller_.faults_seen();
  telemetry_.overruns = controller_.overruns();
  telemetry_.warnings = controller_.warnings();
  telemetry_.planting = controller_.planting();
  telemetry_.planting.damage_seen = static_cast<double>(controller_.damage_seen());
}

}  // namespace planter
