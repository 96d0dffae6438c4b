// One scenario, two drivers, one timeline: the lockstep runner and the real-time driver (the
// loop behind `planter-sim devices`, here with the controller in process and wake-ups that come
// late as a loaded machine's do) must agree on what happens when: planting, the operator's
// presses at a planting-off stop, driving off, the e-stop.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "firmware/controller/control_cycle.h"
#include "hal/sim/sim_gpio.h"
#include "hal/sim/virtual_can_bus.h"
#include "sim/machine/realtime_driver.h"
#include "sim/runner/lockstep_runner.h"

using namespace planter;
using namespace planter::sim;

namespace {

Scenario stop_and_estop() {
  Scenario s = load_scenario(std::string(PLANTER_SOURCE_DIR) + "/scenarios/zhangqiu-field.toml");
  s.plant.route.distance_m = 0.8;
  s.plant.route.stops = {StopEvent{0.4, 14.0, true}};  // a belt refill, planting off
  s.faults.estop_at_s = 40.0;
  s.faults.estop_release_at_s = 41.0;
  return s;
}

std::vector<TimelineEvent> lockstep_timeline(const Scenario& s, double until_s) {
  LockstepRunner r(s);
  while (r.time_s() < until_s) r.step();
  return r.timeline();
}

// The controller's board lines, in process: what the driver drives, the controller reads.
class InProcessLines final : public MachineLines {
 public:
  void line_edge(const hal::GpioEdge& e) override { encoder.push(e); }
  void set_estop(bool asserted) override { estop.set(asserted); }
  bool lamp() override { return status.on(); }

  hal::sim::SimEdgeSource encoder{1 << 14};
  hal::sim::SimDigitalInput estop;
  hal::sim::SimDigitalOutput status;
};

// planterd's 10 ms tick on one thread and the devices' 1 ms wake-ups on another, interleaved in
// wall-time order; one wake-up in 15 comes 4-9 ms late and the controller's ticks jitter too.
std::vector<TimelineEvent> realtime_timeline(const Scenario& s, double until_s) {
  hal::sim::VirtualCanBus bus(s.board.controller.can.bitrate_bps);
  InProcessLines lines;
  auto& endpoint = bus.add_endpoint(512);
  hal::ControllerHal hal{endpoint, lines.encoder, lines.estop, lines.status};
  ControlCycle controller(s.board.controller, hal);
  SimulatedMachine machine(s, bus);
  RealtimeDriver driver(s, machine, lines);
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::int64_t> jitter_ns(0, 300'000);
  std::uniform_int_distribution<int> late(0, 14);
  std::uniform_int_distribution<std::int64_t> late_ns(4'000'000, 9'000'000);
  const std::int64_t period = s.board.controller.can.sync_period_ns;
  const auto until_ns = static_cast<std::int64_t>(until_s * 1e9);
  std::int64_t wake_ns = 0, tick_ns = 0, last_tick_ns = -period;
  while (wake_ns < until_ns) {
    if (tick_ns <= wake_ns) {
      controller.tick(tick_ns, tick_ns - last_tick_ns);
      last_tick_ns = tick_ns;
      tick_ns += period + jitter_ns(rng) - 150'000;
      continue;
    }
    driver.process_devices();
    ControllerView view;
    view.state_known = true;
    view.state = controller.state();
    view.link_resets = controller.link_resets();
    const OperatorPresses p = driver.catch_up(wake_ns, view);
    if (p.run) controller.request_run();
    if (p.stop) controller.request_stop();
    wake_ns += 1'000'000 + jitter_ns(rng) + (late(rng) == 0 ? late_ns(rng) : 0);
  }
  return driver.script().timeline();
}

std::string show(const std::vector<TimelineEvent>& events) {
  std::string s;
  for (const auto& e : events) s += "  " + std::to_string(e.t_s) + " s  " + e.what + "\n";
  return s;
}

}  // namespace

TEST(ScenarioDrivers, LockstepAndRealtimeGiveTheSameTimeline) {
  const Scenario s = stop_and_estop();
  const auto a = lockstep_timeline(s, 45.0);
  const auto b = realtime_timeline(s, 45.0);
  // The scenario's whole story, in order: plant, drive off, stop for the refill, run again,
  // e-stop and its release.
  std::vector<std::string> expected = {
      "run pressed", "planting", "moving",         "stop pressed",     "planting stopped",
      "run pressed", "planting", "e-stop pressed", "planting stopped", "e-stop released"};
  ASSERT_EQ(a.size(), expected.size()) << "lockstep:\n" << show(a);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].what, expected[i]) << show(a);
  ASSERT_EQ(b.size(), a.size()) << "lockstep:\n" << show(a) << "real time:\n" << show(b);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(b[i].what, a[i].what) << "lockstep:\n" << show(a) << "real time:\n" << show(b);
    // Within two control periods: the drivers differ only in when, inside a period, the
    // controller and the machine take their turns, and in the late wake-ups.
    EXPECT_NEAR(b[i].t_s, a[i].t_s, 0.025) << a[i].what << "\nlockstep:\n"
                                           << show(a) << "real time:\n"
                                           << show(b);
  }
}
