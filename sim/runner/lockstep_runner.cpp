#include "sim/runner/lockstep_runner.h"

#include <chrono>
#include <cstdio>

namespace planter::sim {
LockstepRunner::LockstepRunner(const Scenario& scenario)
    : scenario_(scenario),
      bus_(scenario.board.controller.can.bitrate_bps),
      period_ns_(scenario.board.controller.can.sync_period_ns) {
  const ControllerConfig& cfg = scenario_.board.controller;
  controller_endpoint_ = &bus_.add_endpoint(512);
  hal_ = std::make_unique<hal::ControllerHal>(
      hal::ControllerHal{*controller_endpoint_, encoder_, estop_, lamp_});
  controller_ = std::make_unique<ControlCycle>(cfg, *hal_);
  rig_ = std::make_unique<PlantRig>(scenario_, bus_);
  summary_.configure(cfg.sigma.sigma, cfg.depth.target_mm, cfg.clamp.ceiling_N, 8.0);
}

LockstepRunner::~LockstepRunner() = default;

hal::sim::VirtualCanEndpoint& LockstepRunner::device_endpoint(NodeRole role) {
  return rig_->endpoint(role);
}

Cia402DriveDevice& LockstepRunner::drive(NodeRole role) { return rig_->drive(role); }

const Plant& LockstepRunner::plant() const { return rig_->plant(); }

void LockstepRunner::apply_events() {
  const double t = time_s();
  const FaultEvents& f = scenario_.faults;
  if (f.estop_at_s >= 0.0)
    estop_.set(t >= f.estop_at_s && (f.estop_release_at_s < 0.0 || t < f.estop_release_at_s));
  rig_->apply_faults(t);
  // The operator presses "run" once the controller is ready, and drives off a little later;
  // after a link-loss reset the machine is meant to run again, as planterd --run does.
  if (controller_->link_resets() != link_resets_seen_) {
    link_resets_seen_ = controller_->link_resets();
    run_requested_ = false;
  }
  if (!run_requested_ && controller_->state() == SupervisorState::kReady) {
    controller_->request_run();
    run_requested_ = true;
  }
  apply_planting_off_stops(t);
  if (controller_->state() == SupervisorState::kRunning && running_since_s_ < 0.0)
    running_since_s_ = t;
  const double push_at_s = scenario_.plant.route.push_at_s;
  const bool pushed = push_at_s >= 0.0 && t >= push_at_s;
  if (!moving_ && (pushed || (running_since_s_ >= 0.0 &&
                              t >= running_since_s_ + scenario_.plant.start_delay_s))) {
    rig_->plant().start_moving();
    moving_ = true;
  }
}

// At a stop with planting off the operator presses stop once the machine stands, and run
// again start_delay_s before the stop ends, as at the first start.
void LockstepRunner::apply_planting_off_stops(double t) {
  const Ground& ground = rig_->plant().ground();
  const int stop = ground.dwelling_stop();
  if (stop >= 0 && stop != switched_off_stop_ &&
      scenario_.plant.route.stops[static_cast<std::size_t>(stop)].planting_off &&
      controller_->state() == SupervisorState::kRunning) {
    controller_->request_stop();
    switched_off_stop_ = stop;
    restart_at_s_ = ground.dwell_until_s() - scenario_.plant.start_delay_s;
  }
  if (restart_at_s_ >= 0.0 && t >= restart_at_s_ &&
      controller_->state() == SupervisorState::kReady) {
    controller_->request_run();
    restart_at_s_ = -1.0;
  }
}

void LockstepRunner::step() {
  apply_events();
  const std::int64_t now = clock_.now_ns();
  controller_->tick(now, period_ns_);
  rig_->process_devices(now);
  for (std::int64_t t = 0; t < period_ns_; t += substep_ns_) {
    rig_->step_plant(now + t, substep_ns_, encoder_);
  }
  clock_.advance_ns(period_ns_);
  const bool running = controller_->state() == SupervisorState::kRunning;
  summary_.add(controller_->telemetry(), rig_->plant().truth(), running,
               running ? time_s() - running_since_s_ : 0.0);
  if (observer_) observer_(TickRecord{controller_->telemetry(), rig_->plant().truth()});
}

Summary LockstepRunner::run() {
  const auto wall0 = std::chrono::steady_clock::now();
  while (time_s() < scenario_.max_duration_s) {
    step();
    if (moving_ && finished_at_s_ < 0.0 && rig_->plant().ground().finished())
      finished_at_s_ = time_s();
    if (finished_at_s_ >= 0.0 && time_s() >= finished_at_s_ + scenario_.tail_s) break;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double plot_m = 3.0;
  Summary s = summary_.finish(rig_->plant().seedlings(), plot_m,
                              static_cast<int>(scenario_.plant.route.distance_m / plot_m + 1e-9));
  s.scenario = scenario_.name;
  s.distance_m = rig_->plant().ground().x_m();
  s.sim_seconds = time_s();
  s.wall_seconds = wall;
  s.realtime_factor = wall > 0 ? s.sim_seconds / wall : 0.0;
  s.can_frames = bus_.frames_transmitted();
  s.can_bus_load_pct = 100.0 * static_cast<double>(bus_.bits_transmitted()) /
                       (static_cast<double>(bus_.bitrate_bps()) * s.sim_seconds);
  s.faults = controller_->faults();
  s.final_state = supervisor_state_name(controller_->state());
  s.route_complete = finished_at_s_ >= 0.0;
  if (!s.route_complete) {
    char note[160];
    std::snprintf(note, sizeof note,
                  "the route was not finished within max_duration_s = %g s: %.2f of %.2f m driven",
                  scenario_.max_duration_s, s.distance_m, scenario_.plant.route.distance_m);
    s.notes.emplace_back(note);
  }
  return s;
}

}  // namespace planter::sim
