#include "sim/machine/scenario_script.h"

#include <cstdio>

namespace planter::sim {

ScenarioScript::ScenarioScript(const Scenario& scenario) : scenario_(scenario) {}

void ScenarioScript::note(double t_s, std::string what) {
  timeline_.push_back(TimelineEvent{t_s, std::move(what)});
}

ScriptActions ScenarioScript::step(double t_s, const ControllerView& c, const Ground& ground) {
  ScriptActions a;
  const FaultEvents& f = scenario_.faults;
  // The world.
  a.estop = f.estop_at_s >= 0.0 && t_s >= f.estop_at_s &&
            (f.estop_release_at_s < 0.0 || t_s < f.estop_release_at_s);
  if (a.estop != estop_) note(t_s, a.estop ? "e-stop pressed" : "e-stop released");
  estop_ = a.estop;
  if (!f.silent_node.empty() && f.silent_at_s >= 0.0 && t_s >= f.silent_at_s) {
    for (std::size_t i = 0; i < kNodeCount; ++i) {
      if (f.silent_node == node_role_name(static_cast<NodeRole>(i)))
        a.silent_node = static_cast<int>(i);
    }
    if (!silent_) note(t_s, f.silent_node + " silent");
    silent_ = true;
  }
  if (c.lamp != lamp_) note(t_s, c.lamp ? "planting" : "planting stopped");
  lamp_ = c.lamp;

  // The operator presses "run" once the controller is ready; after a link-loss reset the
  // machine is meant to run again, as planterd --run does.
  if (c.state_known && scenario_.operator_presses_run) {
    if (c.link_resets != link_resets_seen_) {
      link_resets_seen_ = c.link_resets;
      run_requested_ = false;
    }
    if (!run_requested_ && c.state == SupervisorState::kReady) {
      a.request_run = true;
      run_requested_ = true;
    }
  }
  // At a stop with planting off the operator presses stop once the machine stands, and run
  // again start_delay_s before the stop ends, as at the first start.
  const int stop = ground.dwelling_stop();
  if (stop >= 0 && stop != switched_off_stop_ &&
      scenario_.plant.route.stops[static_cast<std::size_t>(stop)].planting_off && c.lamp) {
    a.request_stop = true;
    switched_off_stop_ = stop;
    restart_at_s_ = ground.dwell_until_s() - scenario_.plant.start_delay_s;
  }
  if (restart_at_s_ >= 0.0 && t_s >= restart_at_s_ && c.state_known &&
      c.state == SupervisorState::kReady && scenario_.operator_presses_run) {
    a.request_run = true;
    restart_at_s_ = -1.0;
  }
  if (a.request_run) note(t_s, "run pressed");
  if (a.request_stop) note(t_s, "stop pressed");

  // The machine drives off start_delay_s after planting began, or when someone pushes it.
  if (c.lamp && planting_since_s_ < 0.0) planting_since_s_ = t_s;
  const double push_at_s = scenario_.plant.route.push_at_s;
  const bool pushed = push_at_s >= 0.0 && t_s >= push_at_s;
  if (!moving_ && (pushed || (planting_since_s_ >= 0.0 &&
                              t_s >= planting_since_s_ + scenario_.plant.start_delay_s))) {
    a.start_moving = true;
    moving_ = true;
    note(t_s, "moving");
  }
  return a;
}

}  // namespace planter::sim
