#include "sim/hil/realtime_devices.h"

#include <csignal>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "hal/linux/epoll_timer.h"
#include "hal/linux/monotonic_clock.h"
#include "hal/linux/socketcan_bus.h"
#include "sim/hil/can_bridge.h"
#include "sim/hil/gpio_sim_lines.h"
#include "sim/runner/plant_rig.h"

namespace planter::sim {
RealtimeDevicesResult run_realtime_devices(const Scenario& scenario,
                                           const RealtimeDevicesOptions& options,
                                           const std::atomic<bool>& stop) {
  using hal::linux_backend::monotonic_now_ns;
  const config::GpioLines& lines = scenario.board.gpio;
  const bool estop_active_low = scenario.board.controller.estop_active_low;
  hal::linux_backend::SocketCanBus socket(options.can_interface);
  GpioSimLines gpio(options.gpio_chip,
                    {lines.encoder_a, lines.encoder_b, lines.estop, lines.status});
  enum { kA = 0, kB = 1, kEstop = 2 };
  std::fprintf(stderr, "planter-sim devices: nodes %d %d %d %d on %s, encoder on %s\n",
               scenario.board.controller.node(NodeRole::kDiscDrive).node_id,
               scenario.board.controller.node(NodeRole::kRollerActuator).node_id,
               scenario.board.controller.node(NodeRole::kDepthActuator).node_id,
               scenario.board.controller.node(NodeRole::kForceSensor).node_id,
               options.can_interface.c_str(), options.gpio_chip.c_str());
  hal::sim::VirtualCanBus bus(scenario.board.controller.can.bitrate_bps);
  PlantRig rig(scenario, bus);
  CanBridge bridge(socket, bus);
  hal::sim::SimEdgeSource edges;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> truth(nullptr, &std::fclose);
  if (!options.truth_path.empty()) {
    truth.reset(std::fopen(options.truth_path.c_str(), "w"));
    if (!truth) throw std::runtime_error(options.truth_path + ": cannot open for writing");
    std::fprintf(truth.get(),
                 "# source: planter-sim devices\n# scenario: %s\n"
                 "t,wall_time,x_m,v_ground,true_sigma,true_omega,true_clamp_force,"
                 "true_depth_mm,moving,estop\n",
                 scenario.name.c_str());
  }

  const std::int64_t step_ns = 1'000'000;
  hal::linux_backend::EpollTimer timer(step_ns);
  int watched_fd = socket.fd();
  timer.watch(watched_fd);
  gpio.set(kA, false);
  gpio.set(kB, false);
  gpio.set(kEstop, estop_active_low);  // released before the controller looks at it
  const FaultEvents& faults = scenario.faults;
  const std::int64_t start_ns = monotonic_now_ns();
  std::int64_t sim_ns = 0;
  std::int64_t enabled_since_ns = -1;
  bool moving = false;
  bool estop_shown = false;
  bool silent_shown = false;
  double finished_at_s = -1.0;
  RealtimeDevicesResult result;
  std::uint64_t steps = 0;
  while (!stop) {
    const std::uint64_t expired = timer.wait();
    bridge.inbound();
    rig.process_devices(sim_ns);
    if (expired > 0) {
      const std::int64_t wall = monotonic_now_ns() - start_ns;
      if (wall - sim_ns > 5 * step_ns) ++result.late_steps;
      // Catch up to wall time in fixed steps so the physics never sees a long step.
      while (sim_ns + step_ns <= wall) {
        const double t = static_cast<double>(sim_ns) * 1e-9;
        rig.apply_faults(t);
        if (!silent_shown && !faults.silent_node.empty() && faults.silent_at_s >= 0.0 &&
            t >= faults.silent_at_s) {
          std::fprintf(stderr, "planter-sim devices: %s silent at wall %.6f\n",
                       faults.silent_node.c_str(),
                       static_cast<double>(hal::linux_backend::realtime_now_ns()) * 1e-9);
          silent_shown = true;
        }
        const bool estop = faults.estop_at_s >= 0.0 && t >= faults.estop_at_s &&
                           (faults.estop_release_at_s < 0.0 || t < faults.estop_release_at_s);
        if (estop != estop_shown) {
          std::fprintf(stderr, "planter-sim devices: e-stop %s at wall %.6f\n",
                       estop ? "pressed" : "released",
                       static_cast<double>(hal::linux_backend::realtime_now_ns()) * 1e-9);
          estop_shown = estop;
        }
        gpio.set(kEstop, estop_active_low ? !estop : estop);
        // Drives off once the disc drive has been enabled for the scenario's start delay.
        if (rig.drive(NodeRole::kDiscDrive).enabled()) {
          if (enabled_since_ns < 0) enabled_since_ns = sim_ns;
        } else {
          enabled_since_ns = -1;
        }
        const bool pushed =
            scenario.plant.route.push_at_s >= 0.0 && t >= scenario.plant.route.push_at_s;
        if (!moving &&
            (pushed || (enabled_since_ns >= 0 &&
                        sim_ns - enabled_since_ns >=
                            static_cast<std::int64_t>(scenario.plant.start_delay_s * 1e9)))) {
          rig.plant().start_moving();
          moving = true;
        }
        rig.process_devices(sim_ns);  // after a late wake-up, devices act at every step too
        rig.step_plant(sim_ns, step_ns, edges);
        hal::GpioEdge edge;
        while (edges.next_edge(edge)) gpio.set(edge.line == 0 ? kA : kB, edge.rising);
        sim_ns += step_ns;
        if (truth && ++steps % 10 == 0) {
          const PlantTruth& p = rig.plant().truth();
          std::fprintf(truth.get(), "%.3f,%.6f,%.5f,%.5f,%.4f,%.5f,%.2f,%.3f,%d,%d\n",
                       static_cast<double>(sim_ns) * 1e-9,
                       static_cast<double>(hal::linux_backend::realtime_now_ns()) * 1e-9, p.x_m,
                       p.v_mps, p.sigma, p.disc_omega_radps, p.clamp_force_N, p.depth_mm,
                       moving ? 1 : 0, estop ? 1 : 0);
        }
      }
    }
    bridge.outbound();
    // The socket is reopened after the link went down: watch the new descriptor.
    if (socket.fd() != watched_fd) {
      timer.unwatch(watched_fd);
      watched_fd = socket.fd();
      timer.watch(watched_fd);
    }
    const double t = static_cast<double>(sim_ns) * 1e-9;
    if (moving && finished_at_s < 0.0 && rig.plant().ground().finished()) finished_at_s = t;
    if (options.duration_s > 0.0 ? t >= options.duration_s
                                 : finished_at_s >= 0.0 && t >= finished_at_s + scenario.tail_s)
      break;
  }
  result.seconds = static_cast<double>(sim_ns) * 1e-9;
  result.distance_m = rig.plant().ground().x_m();
  for (const Seedling& s : rig.plant().seedlings().seedlings())
    result.seedlings_planted += s.planted;
  result.frames_in = bridge.frames_in();
  result.frames_out = bridge.frames_out();
  result.frames_lost = bridge.frames_lost();
  result.gpio_writes = gpio.writes();
  result.link_downs = socket.link_down_count();
  result.reopens = socket.reopen_count();
  return result;
}

}  // namespace planter::sim
