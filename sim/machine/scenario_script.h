#pragma once
// What happens to the machine in a scenario besides its physics: the world (the e-stop pressed
// and released, a node falling silent, someone pushing the machine) and the operator (run once
// the controller is ready, drive off start_delay_s after planting began, stop and run again
// around a planting-off stop, run again after a link-loss reset). One script for every driver:
// the lockstep runner, the real-time devices (`planter-sim devices`) and planter-can's
// `--iface sim`, so they cannot disagree on when the machine moves or stops.
#include <cstdint>
#include <string>
#include <vector>

#include "firmware/supervisor/supervisor.h"
#include "sim/plant/ground.h"
#include "sim/runner/scenario.h"

namespace planter::sim {

// What the script sees of the controller. The status lamp (on while planting) is on a GPIO line
// every driver can read; the state is known only where the controller runs in process.
struct ControllerView {
  bool lamp = false;
  bool state_known = false;
  SupervisorState state = SupervisorState::kBoot;
  std::uint32_t link_resets = 0;
};

struct ScriptActions {
  bool estop = false;         // the e-stop line is asserted
  bool start_moving = false;  // the machine starts along its route now
  bool request_run = false;   // the operator presses run
  bool request_stop = false;  // the operator presses stop
  int silent_node = -1;       // NodeRole index of a node that stops answering, or -1
};

// When each thing happened, in scenario time: what drivers are compared on.
struct TimelineEvent {
  double t_s = 0.0;
  std::string what;
};

class ScenarioScript {
 public:
  explicit ScenarioScript(const Scenario& scenario);

  // Once per step, before the controller's tick, with the ground the machine stands on.
  ScriptActions step(double t_s, const ControllerView& controller, const Ground& ground);

  [[nodiscard]] bool moving() const { return moving_; }
  // When the status lamp first came on (-1: not yet).
  [[nodiscard]] double planting_since_s() const { return planting_since_s_; }
  [[nodiscard]] const std::vector<TimelineEvent>& timeline() const { return timeline_; }

 private:
  void note(double t_s, std::string what);

  const Scenario& scenario_;
  std::vector<TimelineEvent> timeline_;
  bool estop_ = false;
  bool silent_ = false;
  bool lamp_ = false;
  bool run_requested_ = false;
  std::uint32_t link_resets_seen_ = 0;
  bool moving_ = false;
  double planting_since_s_ = -1.0;  // first time the lamp came on
  int switched_off_stop_ = -1;      // the stop planting was last switched off at
  double restart_at_s_ = -1.0;      // when the operator presses run again (-1: not pending)
};

}  // namespace planter::sim
