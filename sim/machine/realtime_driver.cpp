#include "sim/machine/realtime_driver.h"

namespace planter::sim {

RealtimeDriver::RealtimeDriver(const Scenario& scenario, SimulatedMachine& machine,
                               MachineLines& lines)
    : machine_(machine),
      lines_(lines),
      script_(scenario),
      estop_driven_(scenario.faults.estop_at_s >= 0.0) {
  lines_.set_estop(false);  // released before the controller looks at it
}

OperatorPresses RealtimeDriver::catch_up(std::int64_t wall_ns, const ControllerView& controller) {
  OperatorPresses presses;
  if (wall_ns - sim_ns_ > 5 * kStepNs) ++late_steps_;
  while (sim_ns_ + kStepNs <= wall_ns) {
    const double t = static_cast<double>(sim_ns_) * 1e-9;
    ControllerView view = controller;
    view.lamp = lines_.lamp();
    const ScriptActions a = script_.step(t, view, machine_.plant().ground());
    if (estop_driven_) lines_.set_estop(a.estop);
    if (a.silent_node >= 0) machine_.silence(static_cast<NodeRole>(a.silent_node));
    if (a.start_moving) machine_.plant().start_moving();
    presses.run = presses.run || a.request_run;
    presses.stop = presses.stop || a.request_stop;
    machine_.process_devices(sim_ns_);  // after a late wake-up, devices act at every step too
    machine_.step_plant(sim_ns_, kStepNs, edges_);
    hal::GpioEdge edge;
    while (edges_.next_edge(edge)) lines_.line_edge(edge);
    sim_ns_ += kStepNs;
    if (script_.moving() && finished_at_s_ < 0.0 && machine_.plant().ground().finished())
      finished_at_s_ = static_cast<double>(sim_ns_) * 1e-9;
    if (on_step) on_step(sim_ns_, a);
  }
  return presses;
}

}  // namespace planter::sim
