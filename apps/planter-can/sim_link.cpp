#include "apps/planter-can/sim_link.h"

namespace planter::cantool {
namespace {

constexpr std::int64_t kStepNs = sim::RealtimeDriver::kStepNs;

// The spare node: a second load cell, straight from the box (node-ID 0xFF).
sim::DeviceIdentity spare_identity() {
  sim::DeviceIdentity id;
  id.node_id = canopen::kUnconfiguredNodeId;
  id.device_type = 404;
  id.vendor_id = 0x000000CD;
  id.product_code = 0x00404001;
  id.revision = 2;
  id.serial = 0x00C0FFEE;
  id.name = "sim spare load cell";
  return id;
}

}  // namespace

SimLink::SimLink(const sim::Scenario& scenario, const SimLinkOptions& options)
    : scenario_(scenario), options_(options), bus_(scenario.board.controller.can.bitrate_bps) {
  scenario_.plant.route.distance_m = options_.push_distance_m;
  endpoint_ = &bus_.add_endpoint(1 << 14);
  rig_ = std::make_unique<sim::SimulatedMachine>(scenario_, bus_);
  driver_ = std::make_unique<sim::RealtimeDriver>(scenario_, *rig_,
                                                  static_cast<sim::MachineLines&>(*this));
  if (options_.spare_node) {
    spare_ = std::make_unique<sim::Cia404ForceSensor>(spare_identity(), bus_.add_endpoint(256));
    spare_->power_on(0);
  }
  if (options_.with_controller) {
    auto& ep = bus_.add_endpoint(512);
    hal_ = std::make_unique<hal::ControllerHal>(
        hal::ControllerHal{ep, controller_edges_, estop_, lamp_});
    controller_ = std::make_unique<ControlCycle>(scenario_.board.controller, *hal_);
    // planterd has been running when the engineer plugs in: let it boot the nodes first, so the
    // tool's first SDO request does not meet the controller's boot SDOs on the same node.
    const std::int64_t limit =
        scenario_.board.controller.supervisor.boot_timeout_ns + 1'000'000'000;
    while (clock_.now_ns() < limit) {
      const SupervisorState s = controller_->state();
      if (s == SupervisorState::kReady || s == SupervisorState::kRunning ||
          s == SupervisorState::kFault) {
        break;
      }
      advance();
    }
    hal::CanFrame f;
    while (endpoint_->receive(f)) {
    }  // the tool was not listening yet
  }
}

SimLink::~SimLink() = default;

// One millisecond of the machine, as the real-time driver steps it, with planterd's tick when
// due. The engineer is the operator here: the scenario's operator never presses a button
// (the controller's state is not shown to the script), and the machine moves when pushed.
void SimLink::advance() {
  const std::int64_t now = clock_.now_ns();
  if (controller_ && now >= next_tick_ns_) {
    const std::int64_t period = scenario_.board.controller.can.sync_period_ns;
    controller_->tick(now, period);
    next_tick_ns_ = now + period;
  }
  if (spare_) spare_->process(now);
  driver_->catch_up(now + kStepNs, sim::ControllerView{});
  clock_.advance_ns(kStepNs);
}

void SimLink::line_edge(const hal::GpioEdge& edge) {
  hal::GpioEdge e = edge;
  if (options_.encoder_wires_swapped && e.line <= 1) e.line = static_cast<std::uint8_t>(1 - e.line);
  tool_edges_.push(e);
  if (controller_) controller_edges_.push(e);
}

bool SimLink::wait(std::int64_t deadline_ns) {
  for (;;) {
    if (endpoint_->pending() > 0) return true;
    if (clock_.now_ns() >= deadline_ns) return false;
    advance();
  }
}

void SimLink::set_load_N(double load_N) { rig_->plant().set_fixture_load_N(load_N); }

void SimLink::push_machine() {
  if (!moving_) rig_->plant().start_moving();
  moving_ = true;
}

}  // namespace planter::cantool
