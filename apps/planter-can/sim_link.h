#pragma once
// `--iface sim`: the simulated machine in-process. Its four CANopen nodes (and a spare,
// unconfigured load cell that waits for an ID over LSS) sit on a virtual bus with the plant;
// optionally the controller runs too, as planterd would on the board. Time is simulated: a
// wait advances the machine's clock in 1 ms steps, so a 2 s scan costs milliseconds.
#include <memory>
#include <optional>

#include "apps/planter-can/tool_link.h"
#include "firmware/controller/control_cycle.h"
#include "hal/sim/sim_clock.h"
#include "hal/sim/sim_gpio.h"
#include "hal/sim/virtual_can_bus.h"
#include "sim/machine/realtime_driver.h"
#include "sim/machine/simulated_machine.h"

namespace planter::cantool {

struct SimLinkOptions {
  bool with_controller = false;  // planterd running: SYNC, PDOs, heartbeats on the bus
  bool spare_node = true;        // an unconfigured node for LSS
  double push_distance_m = 5.0;  // how far the fixture pushes the machine (soil-wheel calibration)
  bool encoder_wires_swapped = false;  // A and B crossed at the connector (a wiring fault)
};

class SimLink final : public ToolLink, public SimFixture, private sim::MachineLines {
 public:
  SimLink(const sim::Scenario& scenario, const SimLinkOptions& options);
  ~SimLink() override;

  bool wait(std::int64_t deadline_ns) override;
  std::int64_t now_ns() override { return clock_.now_ns(); }
  std::int64_t wall_time_ns() override { return clock_.now_ns(); }
  hal::GpioEdgeSource* encoder() override { return &tool_edges_; }
  SimFixture* fixture() override { return this; }
  [[nodiscard]] std::string name() const override { return "sim"; }
  [[nodiscard]] hal::CanBusCounters counters() const override { return endpoint_->counters(); }

  void set_load_N(double load_N) override;
  void push_machine() override;

  // Advances the machine by one millisecond.
  void advance();
  hal::sim::VirtualCanBus& bus() { return bus_; }
  sim::SimulatedMachine& rig() { return *rig_; }
  [[nodiscard]] const ControlCycle* controller() const { return controller_.get(); }
  [[nodiscard]] const sim::Scenario& scenario() const { return scenario_; }

 protected:
  bool try_send(const hal::CanFrame& frame) override { return endpoint_->send(frame); }
  bool try_receive(hal::CanFrame& frame) override { return endpoint_->receive(frame); }
  void back_off() override { advance(); }

 private:
  sim::Scenario scenario_;
  SimLinkOptions options_;
  hal::sim::VirtualCanBus bus_;
  hal::sim::SimClock clock_;
  hal::sim::VirtualCanEndpoint* endpoint_ = nullptr;
  std::unique_ptr<sim::SimulatedMachine> rig_;
  std::unique_ptr<sim::RealtimeDriver> driver_;
  std::unique_ptr<sim::Cia404ForceSensor> spare_;
  hal::sim::SimEdgeSource tool_edges_{1 << 16};
  hal::sim::SimEdgeSource controller_edges_{1 << 16};
  // The controller, when it runs.
  hal::sim::SimDigitalInput estop_;
  hal::sim::SimDigitalOutput lamp_;
  std::unique_ptr<hal::ControllerHal> hal_;
  std::unique_ptr<ControlCycle> controller_;
  std::int64_t next_tick_ns_ = 0;
  bool moving_ = false;

  // The machine's lines, as the driver drives them: to the tool's and the controller's inputs.
  void line_edge(const hal::GpioEdge& edge) override;
  void set_estop(bool asserted) override { estop_.set(asserted); }
  bool lamp() override { return lamp_.on(); }
};

}  // namespace planter::cantool
