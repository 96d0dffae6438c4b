#include "sim/apps/live.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <limits>
#include <thread>

#include "sim/runner/lockstep_runner.h"
#include "sim/runner/summary.h"

namespace planter::sim {
namespace {
std::atomic<bool> g_stop{false};  // set by SIGINT/SIGTERM: the only way a signal can talk
extern "C" void on_signal(int) { g_stop.store(true); }
}  // namespace

int run_live(const std::string& scenario_path, const LiveOptions& options) {
  const Scenario scenario = load_scenario(scenario_path);
  const ControllerConfig& cfg = scenario.board.controller;
  console::ConsoleInfo info;
  info.title = scenario.name + " (simulated)";
  info.clamp_ceiling_N = cfg.clamp.ceiling_N;
  info.target_spacing_mm = cfg.monitor.target_spacing_mm;
  info.photo_eye = cfg.monitor.sensor_fitted;
  info.simulated = true;
  console::ConsoleServer server(options.console, info);
  server.start();
  std::printf("console: http://%s:%d/  (%s; Ctrl-C to stop)\n", options.console.bind.c_str(),
              server.port(), scenario.name.c_str());
  std::fflush(stdout);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);

  LockstepRunner runner(scenario);
  // Ten samples a second to the console (the page polls five times a second).
  const std::int64_t every = std::max<std::int64_t>(1, 100'000'000 / cfg.can.sync_period_ns);
  std::int64_t tick = 0;
  runner.set_observer([&](const TickRecord& r) {
    if (++tick % every != 0) return;
    console::LiveSample s =
        console::live_sample(static_cast<double>(r.controller.time_ns) * 1e-9, r.controller);
    // The true sigma where the machine moves fast enough for it to mean something.
    s.sigma_true = r.truth.v_mps >= kSigmaMinSpeedMps ? r.truth.sigma
                                                      : std::numeric_limits<double>::quiet_NaN();
    server.publish(s);
  });
  const auto start = std::chrono::steady_clock::now();
  while (!g_stop.load()) {
    runner.step();
    const double t = runner.time_s();
    if (options.duration_s > 0.0 && t >= options.duration_s) break;
    std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                              std::chrono::duration<double>(t / options.speed)));
  }
  server.stop();
  std::printf("console: stopped at %.1f s simulated\n", runner.time_s());
  return 0;
}

}  // namespace planter::sim
