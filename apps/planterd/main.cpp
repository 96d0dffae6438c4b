// planterd: the controller daemon flashed onto the board. Opens the board's CAN interface and
// GPIO lines, boots the CANopen nodes, runs the control loop in a SCHED_FIFO thread, records
// telemetry crash-safely, keeps the systemd watchdog fed while the loop is alive, and stops
// the machine safely on SIGTERM/SIGINT. SIGUSR1 is the operator's fault reset.
#include <pthread.h>
#include <signal.h>
#include <string.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdio>
#include <memory>
#include <mutex>
#include <thread>

#include "apps/planterd/board_hardware.h"
#include "apps/planterd/crash_safe_recording.h"
#include "apps/planterd/service_notify.h"
#include "apps/planterd/spsc_queue.h"
#include "config/commissioning.h"
#include "config/config_error.h"
#include "firmware/controller/control_cycle.h"
#include "hal/linux/hal_error.h"
#include "hal/linux/rt_loop.h"
#include "hal/linux/tick_trace.h"

namespace {

using namespace planter;
using hal::linux_backend::monotonic_now_ns;

struct Options {
  std::string board;
  std::string record;
  bool run = false;
  double duration_s = 0.0;
  int flush_ms = 200;
  double log_period_s = 5.0;
  bool resume_after_link_loss = false;
  std::string commissioned_stamp;  // drives stay off until this stamp matches the board
};

struct Row {
  double t_s;
  Telemetry telemetry;
};

// What the loop thread shares with the main thread: commands in, progress and status out.
struct Shared {
  std::atomic<bool> stop{false};
  std::atomic<bool> fault_reset{false};
  std::atomic<bool> finished{false};
  std::atomic<std::uint64_t> ticks{0};
  std::atomic<std::uint64_t> rows_dropped{0};
  std::atomic<std::uint32_t> link_resets{0};
  std::atomic<bool> commissioned{true};  // false: --run is held back

  std::mutex status_mutex;  // the loop only try_locks it: never blocks
  Telemetry status;
};

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "planterd: %s\n", message.c_str());
  return code;
}

void log_status(const Telemetry& t, const hal::CanBusCounters& can) {
  std::fprintf(stderr,
               "planterd: state %s  v %.3f m/s  sigma %.3f  clamp %.1f N (cmd %.1f)  depth %.1f "
               "mm (cmd %.1f)  faults 0x%x  can tx %u rx %u err %u drop %u ovfl %u  unknown %u\n",
               supervisor_state_name(t.state), t.v_wheel_mps, t.sigma, t.clamp_force_N,
               t.clamp_force_cmd_N, t.depth_mm, t.depth_cmd_mm, t.faults, can.tx_frames,
               can.rx_frames, can.error_frames, can.tx_dropped, can.rx_overflow, t.unknown_frames);
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  CLI::App app{"planterd: the scallion transplanter's controller daemon"};
  app.add_option("--board", opt.board, "board file (boards/<board>/board.toml)")->required();
  app.add_option("--record", opt.record, "record telemetry to this CSV (PRODUCT.md format)");
  app.add_flag("--run", opt.run, "start planting as soon as every node is ready (unattended)");
  app.add_option("--duration", opt.duration_s, "stop safely after this many seconds (tests)")
      ->check(CLI::Range(0.0, 1e7));
  app.add_option("--flush-ms", opt.flush_ms, "recording flush interval: the most a crash loses")
      ->check(CLI::Range(10, 10000));
  app.add_option("--log-period", opt.log_period_s, "status line every N seconds (0 = off)")
      ->check(CLI::Range(0.0, 3600.0));
  app.add_flag("--resume-after-link-loss", opt.resume_after_link_loss,
               "after the CAN link went down and came back, reset the faults it caused and boot "
               "the nodes again (with --run: plant again)");
  app.add_option("--commissioned-stamp", opt.commissioned_stamp,
                 "start the drives (--run) only while this stamp from `planter-can check "
                 "--mark-commissioned` matches the board file");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    return fail(2, std::string(e.what()) + " (planterd --help lists the options)");
  }

  config::BoardConfig board;
  std::unique_ptr<daemon::BoardHardware> hw;
  std::unique_ptr<daemon::CrashSafeRecording> recording;
  // Row times count from here; start_wall in the metadata places them on the wall clock.
  const std::int64_t start_ns = monotonic_now_ns();
  timespec start_wall{};
  clock_gettime(CLOCK_REALTIME, &start_wall);
  char start_wall_text[64];
  std::snprintf(start_wall_text, sizeof start_wall_text, "start_wall: %lld.%06ld",
                static_cast<long long>(start_wall.tv_sec), start_wall.tv_nsec / 1000);
  try {
    board = config::load_board(opt.board);
    for (const auto& w : board.warnings) std::fprintf(stderr, "planterd: warning: %s\n", w.c_str());
    hw = std::make_unique<daemon::BoardHardware>(board);
    if (!opt.record.empty()) {
      recording = std::make_unique<daemon::CrashSafeRecording>(
          opt.record, std::vector<std::string>{
                          "board: " + board.name, "source: planterd", "units: PRODUCT.md v1",
                          "flush_ms: " + std::to_string(opt.flush_ms), start_wall_text});
      if (!recording->moved_aside_to().empty())
        std::fprintf(stderr, "planterd: previous recording moved to %s\n",
                     recording->moved_aside_to().c_str());
    }
  } catch (const config::ConfigError& e) {
    return fail(2, e.what());
  } catch (const hal::linux_backend::HalError& e) {
    return fail(2, std::string(board.file) + ": " + e.what());
  } catch (const std::exception& e) {
    return fail(2, e.what());
  }

  // Signals are taken by the main thread only (sigtimedwait), never by the loop thread.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGUSR1);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  hal::linux_backend::TickTrace trace;  // per-tick phase times, dumped on an overrun
  hw->controller_hal().tick_probe = &trace;
  ControllerConfig controller_config = board.controller;
  controller_config.link_recovery.enabled = opt.resume_after_link_loss;
  controller_config.link_recovery.resume_running = opt.run;
  ControlCycle controller(controller_config, hw->controller_hal());
  daemon::SpscQueue<Row> rows(4096);
  Shared shared;
  if (!opt.commissioned_stamp.empty()) {
    std::string why;
    shared.commissioned = config::commissioned(opt.commissioned_stamp, opt.board, why);
  }
  hal::linux_backend::RtLoopConfig rt_config;
  rt_config.period_ns = board.controller.can.sync_period_ns;
  rt_config.priority = board.realtime.priority;
  rt_config.cpu = board.realtime.cpu;
  rt_config.require_realtime = board.realtime.require;
  hal::linux_backend::RtLoop loop(rt_config);
  std::string rt_refused;
  std::atomic<bool> setup_done{false};
  std::string setup_error;

  std::thread loop_thread([&] {
    try {
      rt_refused = loop.setup();
    } catch (const hal::linux_backend::HalError& e) {
      setup_error = e.what();
      shared.finished = true;
      setup_done = true;
      return;
    }
    setup_done = true;
    const std::int64_t loop_start_ns = monotonic_now_ns();
    const std::int64_t duration_ns = static_cast<std::int64_t>(opt.duration_s * 1e9);
    const std::int64_t stop_grace_ns = 5'000'000'000;
    std::int64_t stop_at_ns = -1;
    bool run_requested = false;
    std::uint32_t link_resets_seen = 0;
    loop.run([&](std::int64_t now, std::int64_t dt) {
      trace.begin(now, loop.last_late_ns(), dt);
      // After a link-loss reset (firmware/supervisor/link_recovery.h) the run is asked for again.
      if (controller.link_resets() != link_resets_seen) {
        link_resets_seen = controller.link_resets();
        shared.link_resets.store(link_resets_seen, std::memory_order_relaxed);
        run_requested = false;
      }
      if (duration_ns > 0 && now - loop_start_ns >= duration_ns) shared.stop = true;
      if (shared.stop && stop_at_ns < 0) {
        controller.request_stop();
        stop_at_ns = now;
      }
      if (shared.fault_reset.exchange(false)) controller.request_fault_reset();
      if (opt.run && !run_requested && controller.state() == SupervisorState::kReady &&
          shared.commissioned.load(std::memory_order_relaxed)) {
        controller.request_run();
        run_requested = true;
      }
      controller.tick(now, dt);
      hw->edge_latency().tick_done(monotonic_now_ns());
      const Telemetry& t = controller.telemetry();
      if (recording && !rows.push(Row{static_cast<double>(now - start_ns) * 1e-9, t}))
        shared.rows_dropped.fetch_add(1, std::memory_order_relaxed);
      if (shared.status_mutex.try_lock()) {
        shared.status = t;
        shared.status_mutex.unlock();
      }
      trace.phase_done(hal::TickPhase::kHandOff);
      // An overrun as the supervisor counts it: every one must be explainable from the log.
      if (dt > board.controller.supervisor.overrun_threshold_ns ||
          loop.last_late_ns() >= rt_config.period_ns) {
        trace.capture_overrun();
      }
      shared.ticks.fetch_add(1, std::memory_order_release);
      if (stop_at_ns < 0) return true;
      // Safe stop: the drives are brought to rest by the controller; leave once they are.
      const SupervisorState s = controller.state();
      const bool at_rest = s != SupervisorState::kRunning && s != SupervisorState::kStopping;
      return !(at_rest || now - stop_at_ns > stop_grace_ns);
    });
    shared.finished = true;
  });

  while (!setup_done) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  if (!setup_error.empty()) {
    loop_thread.join();
    return fail(2, setup_error);
  }
  if (!rt_refused.empty())
    std::fprintf(stderr, "planterd: warning: running without real-time guarantees: %s\n",
                 rt_refused.c_str());
  std::fprintf(stderr, "planterd: board %s, CAN %s, GPIO %s, loop %.1f ms\n", board.name.c_str(),
               board.can_interface.c_str(), board.gpio.chip.c_str(),
               static_cast<double>(rt_config.period_ns) * 1e-6);
  daemon::ServiceNotifier service;
  service.notify("READY=1\nSTATUS=booting CANopen nodes");

  std::uint64_t watchdog_us = 0;
  const bool watchdog = service.watchdog_enabled(watchdog_us);
  std::uint64_t ticks_at_last_kick = 0;
  std::int64_t next_log_ns = monotonic_now_ns();
  std::int64_t next_kick_ns = monotonic_now_ns();
  SupervisorState logged_state = SupervisorState::kBoot;
  std::string not_commissioned_logged;
  std::int64_t next_stamp_check_ns = 0;
  bool recording_ok = true;
  Row row{};
  while (!shared.finished) {
    timespec wait{};
    wait.tv_nsec = static_cast<long>(opt.flush_ms) * 1'000'000 % 1'000'000'000;
    wait.tv_sec = opt.flush_ms / 1000;
    const int sig = sigtimedwait(&signals, nullptr, &wait);
    if (sig == SIGTERM || sig == SIGINT) {
      if (!shared.stop) std::fprintf(stderr, "planterd: %s: stopping safely\n", strsignal(sig));
      shared.stop = true;
      service.notify("STOPPING=1");
    } else if (sig == SIGUSR1) {
      shared.fault_reset = true;
    }
    if (recording) {
      while (rows.pop(row)) recording->add(row.t_s, row.telemetry);
      if (!recording->flush() && recording_ok) {
        std::fprintf(stderr, "planterd: %s: write failed; recording stopped\n", opt.record.c_str());
        recording_ok = false;
      }
    }
    if (const std::string overrun = trace.take_report(); !overrun.empty()) {
      std::fprintf(stderr, "planterd: %s", overrun.c_str());
    }
    Telemetry status;
    {
      std::lock_guard<std::mutex> lock(shared.status_mutex);
      status = shared.status;
    }
    const std::int64_t now = monotonic_now_ns();
    const std::uint64_t ticks = shared.ticks.load(std::memory_order_acquire);
    if (!opt.commissioned_stamp.empty() && now >= next_stamp_check_ns) {
      // Looked at once a second, so a check that passes lets the drives start without a restart.
      std::string why;
      const bool ok = config::commissioned(opt.commissioned_stamp, opt.board, why);
      shared.commissioned = ok;
      if (!ok && why != not_commissioned_logged) {
        std::fprintf(stderr, "planterd: drives stay off: %s\n", why.c_str());
        service.notify("STATUS=not commissioned: " + why);
      } else if (ok && !not_commissioned_logged.empty()) {
        std::fprintf(stderr, "planterd: commissioning stamp %s matches the board\n",
                     opt.commissioned_stamp.c_str());
      }
      not_commissioned_logged = ok ? "" : why;
      next_stamp_check_ns = now + 1'000'000'000;
    }
    // Feed the watchdog only while the control loop makes progress.
    if (watchdog && now >= next_kick_ns && ticks != ticks_at_last_kick) {
      service.notify("WATCHDOG=1");
      ticks_at_last_kick = ticks;
      next_kick_ns = now + static_cast<std::int64_t>(watchdog_us) * 1000 / 2;
    }
    if (status.state != logged_state) {
      std::fprintf(stderr, "planterd: %s -> %s (faults 0x%x)\n",
                   supervisor_state_name(logged_state), supervisor_state_name(status.state),
                   status.faults);
      service.notify(std::string("STATUS=") + supervisor_state_name(status.state));
      logged_state = status.state;
    }
    if (opt.log_period_s > 0 && now >= next_log_ns) {
      log_status(status, hw->can().counters());
      next_log_ns = now + static_cast<std::int64_t>(opt.log_period_s * 1e9);
    }
  }
  loop_thread.join();
  if (recording) {
    while (rows.pop(row)) recording->add(row.t_s, row.telemetry);
    recording_ok = recording->flush() && recording_ok;
  }
  const auto& lat = loop.latency();
  const auto& edge = hw->edge_latency().histogram();
  std::fprintf(stderr,
               "planterd: encoder edge to CAN command: %llu edges, p50 %.0f us p99 %.0f us max "
               "%.0f us\n",
               static_cast<unsigned long long>(edge.count()), edge.percentile_us(50),
               edge.percentile_us(99), edge.max_us());
  const hal::CanBusCounters can = hw->can().counters();
  std::fprintf(
      stderr,
      "planterd: stopped in %s after %llu ticks; wake-up latency p50 %.0f us p99 %.0f "
      "us max %.0f us; overruns %llu; CAN link downs %u reopens %u, error frames %u, "
      "tx dropped %u, rx overflow %u; unknown frames %u; rows dropped %llu; link-loss resets "
      "%u\n",
      supervisor_state_name(controller.state()), static_cast<unsigned long long>(loop.ticks()),
      lat.percentile_us(50), lat.percentile_us(99), lat.max_us(),
      static_cast<unsigned long long>(loop.overruns()), hw->can().link_down_count(),
      hw->can().reopen_count(), can.error_frames, can.tx_dropped, can.rx_overflow,
      controller.telemetry().unknown_frames,
      static_cast<unsigned long long>(shared.rows_dropped.load()), shared.link_resets.load());
  return recording_ok ? 0 : 1;
}
