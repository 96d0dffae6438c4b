#pragma once
// Runs the firmware controller, the simulated bus and devices, and the plant in one thread
// that owns simulated time: controller tick -> devices -> plant sub-steps, every period.
// Deterministic for a given scenario and seed.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "firmware/controller/control_cycle.h"
#include "hal/sim/sim_clock.h"
#include "hal/sim/sim_gpio.h"
#include "hal/sim/virtual_can_bus.h"
#include "sim/plant/plant.h"
#include "sim/runner/plant_rig.h"
#include "sim/runner/scenario.h"
#include "sim/runner/summary.h"

namespace planter::sim {

// One row per control tick: what the recording, the summary and the report are made from.
struct TickRecord {
  const Telemetry& controller;
  const PlantTruth& truth;
};

class LockstepRunner {
 public:
  explicit LockstepRunner(const Scenario& scenario);
  ~LockstepRunner();

  // Called after every tick (recording, tests). May be empty.
  using Observer = std::function<void(const TickRecord&)>;
  void set_observer(Observer observer) { observer_ = std::move(observer); }

  // Runs to the end of the scenario; returns the summary.
  Summary run();
  // Runs a single control period (for tests that drive the loop themselves).
  void step();

  ControlCycle& controller() { return *controller_; }
  hal::sim::VirtualCanBus& bus() { return bus_; }
  hal::sim::SimDigitalInput& estop() { return estop_; }
  hal::sim::VirtualCanEndpoint& device_endpoint(NodeRole role);
  // The controller's own connection to the bus (unplug it to pull the controller's cable).
  hal::sim::VirtualCanEndpoint& controller_endpoint() { return *controller_endpoint_; }
  Cia402DriveDevice& drive(NodeRole role);
  [[nodiscard]] const Plant& plant() const;
  [[nodiscard]] double time_s() const { return static_cast<double>(clock_.now_ns()) * 1e-9; }
  [[nodiscard]] const Scenario& scenario() const { return scenario_; }

 private:
  void apply_events();
  void apply_planting_off_stops(double t);

  Scenario scenario_;
  hal::sim::VirtualCanBus bus_;
  hal::sim::SimClock clock_;
  hal::sim::SimEdgeSource encoder_;
  hal::sim::SimDigitalInput estop_;
  hal::sim::SimDigitalOutput lamp_;
  hal::sim::VirtualCanEndpoint* controller_endpoint_;
  std::unique_ptr<hal::ControllerHal> hal_;
  std::unique_ptr<ControlCycle> controller_;
  std::unique_ptr<PlantRig> rig_;
  Observer observer_;
  SummaryBuilder summary_;
  std::int64_t period_ns_;
  std::int64_t substep_ns_ = 1'000'000;
  bool run_requested_ = false;
  std::uint32_t link_resets_seen_ = 0;
  bool moving_ = false;
  double running_since_s_ = -1.0;
  double finished_at_s_ = -1.0;
  int switched_off_stop_ = -1;  // the stop planting was last switched off at
  double restart_at_s_ = -1.0;  // when the operator presses run again (-1: not pending)
};

}  // namespace planter::sim
