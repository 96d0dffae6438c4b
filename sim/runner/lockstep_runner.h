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
#include "sim/machine/scenario_script.h"
#include "sim/machine/simulated_machine.h"
#include "sim/plant/plant.h"
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
  // The simulated receiver's fixes as delivered (empty when the board has none).
  [[nodiscard]] const std::vector<hal::GnssFix>& gnss_fixes() const { return gnss_.log(); }
  hal::sim::VirtualCanEndpoint& device_endpoint(NodeRole role);
  // The controller's own connection to the bus (unplug it to pull the controller's cable).
  hal::sim::VirtualCanEndpoint& controller_endpoint() { return *controller_endpoint_; }
  Cia402DriveDevice& drive(NodeRole role);
  [[nodiscard]] const Plant& plant() const;
  Plant& plant();
  [[nodiscard]] double time_s() const { return static_cast<double>(clock_.now_ns()) * 1e-9; }
  [[nodiscard]] const Scenario& scenario() const { return scenario_; }
  // What happened when (the script's timeline), for comparing drivers.
  [[nodiscard]] const std::vector<TimelineEvent>& timeline() const { return script_.timeline(); }

 private:
  void apply_events();
  void tell_the_clamp_each_stem();  // Scenario::clamp_told_each_stem

  Scenario scenario_;
  ScenarioScript script_;
  hal::sim::VirtualCanBus bus_;
  hal::sim::SimClock clock_;
  hal::sim::SimEdgeSource edges_;  // encoder A/B and the photo-eye
  hal::sim::SimDigitalInput estop_;
  hal::sim::SimDigitalOutput lamp_;
  hal::sim::SimGnss gnss_;  // fitted when the board has a receiver
  hal::sim::VirtualCanEndpoint* controller_endpoint_;
  std::unique_ptr<hal::ControllerHal> hal_;
  std::unique_ptr<ControlCycle> controller_;
  std::unique_ptr<SimulatedMachine> machine_;
  Observer observer_;
  SummaryBuilder summary_;
  LoopScorer scores_;
  std::int64_t period_ns_;
  std::size_t told_stem_ = 0;  // the last stem the clamp was told of (1-based), 0: none
  std::int64_t substep_ns_ = 1'000'000;
  double finished_at_s_ = -1.0;
};

}  // namespace planter::sim
