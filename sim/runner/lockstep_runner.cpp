#include "sim/runner/lockstep_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "firmware/controller/setpoint_rules.h"

namespace planter::sim {
LockstepRunner::LockstepRunner(const Scenario& scenario)
    : scenario_(scenario),
      script_(scenario_),
      bus_(scenario.board.controller.can.bitrate_bps),
      period_ns_(scenario.board.controller.can.sync_period_ns) {
  const ControllerConfig& cfg = scenario_.board.controller;
  controller_endpoint_ = &bus_.add_endpoint(512);
  hal_ = std::make_unique<hal::ControllerHal>(
      hal::ControllerHal{*controller_endpoint_, edges_, estop_, lamp_});
  if (cfg.ground.gnss_fitted) hal_->gnss = &gnss_;
  controller_ = std::make_unique<ControlCycle>(cfg, *hal_);
  machine_ = std::make_unique<SimulatedMachine>(scenario_, bus_);
  if (cfg.ground.gnss_fitted) machine_->fit_gnss(gnss_);
  summary_.configure(cfg.sigma.sigma, cfg.depth.target_mm, cfg.clamp.ceiling_N, 8.0, cfg.monitor);
  // The depth is judged once the opener has had time to ramp down from raised, and a second.
  scores_.configure(
      cfg.sigma.sigma, cfg.clamp.ceiling_N,
      std::abs(cfg.depth.target_mm - cfg.depth.raised_mm) / cfg.depth.rate_mm_per_s + 1.0,
      static_cast<double>(period_ns_) * 1e-9);
}

LockstepRunner::~LockstepRunner() = default;

hal::sim::VirtualCanEndpoint& LockstepRunner::device_endpoint(NodeRole role) {
  return machine_->endpoint(role);
}

Cia402DriveDevice& LockstepRunner::drive(NodeRole role) { return machine_->drive(role); }

const Plant& LockstepRunner::plant() const { return machine_->plant(); }
Plant& LockstepRunner::plant() { return machine_->plant(); }

// The scenario's script decides; the runner delivers: the e-stop line, a silent node, the
// operator's buttons, and the start along the route.
void LockstepRunner::apply_events() {
  ControllerView view;
  view.lamp = lamp_.on();
  view.state_known = true;
  view.state = controller_->state();
  view.link_resets = controller_->link_resets();
  const ScriptActions a = script_.step(time_s(), view, machine_->plant().ground());
  if (scenario_.faults.estop_at_s >= 0.0) estop_.set(a.estop);
  if (a.silent_node >= 0) machine_->silence(static_cast<NodeRole>(a.silent_node));
  if (a.request_run) controller_->request_run();
  if (a.request_stop) controller_->request_stop();
  if (a.start_moving) machine_->plant().start_moving();
}

// The bound's oracle: each stem's peak at the nip's scale, as it comes in, 5 % below (the
// per-stem rule's margin), never above the machine's set-point. Through the operator's command,
// so the loop ramps to it as to any set-point.
void LockstepRunner::tell_the_clamp_each_stem() {
  const SeedlingProcess& stems = machine_->plant().seedlings();
  const std::size_t in_nip = stems.seedling_in_nip(time_s());
  if (in_nip == 0 || in_nip == told_stem_) return;
  told_stem_ = in_nip;
  const ClampLoopConfig& clamp = scenario_.board.controller.clamp;
  const double peak_N = stems.seedlings()[in_nip - 1].nip.peak_N;
  const double aim_N = std::min(clamp.setpoint_N, 0.95 * peak_N);
  const SetpointRange range = clamp_force_range_N(scenario_.board.controller);
  controller_->command({CommandKind::kSetClampForce, std::clamp(aim_N, range.min, range.max)});
}

void LockstepRunner::step() {
  apply_events();
  if (scenario_.clamp_told_each_stem) tell_the_clamp_each_stem();
  const std::int64_t now = clock_.now_ns();
  controller_->tick(now, period_ns_);
  machine_->process_devices(now);
  for (std::int64_t t = 0; t < period_ns_; t += substep_ns_) {
    machine_->step_plant(now + t, substep_ns_, edges_);
  }
  clock_.advance_ns(period_ns_);
  const bool running = controller_->state() == SupervisorState::kRunning;
  summary_.add(controller_->telemetry(), machine_->plant().truth(), running,
               running ? time_s() - script_.planting_since_s() : 0.0);
  scores_.add(controller_->telemetry(), machine_->plant().truth(), time_s());
  if (observer_) observer_(TickRecord{controller_->telemetry(), machine_->plant().truth()});
}

Summary LockstepRunner::run() {
  const auto wall0 = std::chrono::steady_clock::now();
  while (time_s() < scenario_.max_duration_s) {
    step();
    if (script_.moving() && finished_at_s_ < 0.0 && machine_->plant().ground().finished())
      finished_at_s_ = time_s();
    if (finished_at_s_ >= 0.0 && time_s() >= finished_at_s_ + scenario_.tail_s) break;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double plot_m = 3.0;
  Summary s = summary_.finish(machine_->plant().seedlings(), plot_m,
                              static_cast<int>(scenario_.plant.route.distance_m / plot_m + 1e-9));
  s.scenario = scenario_.name;
  s.board = scenario_.board.name;
  s.board_is_hardware = scenario_.board.can_interface != "sim";
  s.loops = scores_.finish();
  s.distance_m = machine_->plant().ground().x_m();
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
