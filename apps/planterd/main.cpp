// planterd: the controller daemon flashed onto the board. Opens the board's CAN interface and
// GPIO lines, boots the CANopen nodes, runs the control loop in a SCHED_FIFO thread, records
// telemetry crash-safely, keeps the systemd watchdog fed while the loop is alive, and stops
// the machine safely on SIGTERM/SIGINT. SIGUSR1 is the operator's fault reset. Where the board
// sets a [console] port (and the host build has cpp-httplib), it serves the operator's console:
// the loop publishes samples and answers commands through lock-free queues, never waiting.
#include <pthread.h>
#include <signal.h>
#include <string.h>

#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <thread>

#include "apps/planterd/as_planted_log.h"
#include "apps/planterd/board_hardware.h"
#include "apps/planterd/console_recording.h"
#include "apps/planterd/crash_safe_recording.h"
#include "apps/planterd/service_notify.h"
#include "config/cli_range.h"
#include "config/commissioning.h"
#include "config/config_error.h"
#include "config/recording_format.h"
#include "console/client_address.h"
#include "console/command_channel.h"
#include "console/live_sample.h"
#include "console/spsc_queue.h"
#ifdef PLANTERD_WITH_CONSOLE
#include "console/console_server.h"
#endif
#include "apps/version/cli_errors.h"
#include "apps/version/list_keys.h"
#include "apps/version/version.h"
#include "config/board_keys.h"
#include "firmware/controller/control_cycle.h"
#include "hal/linux/hal_error.h"
#include "hal/linux/rt_loop.h"
#include "hal/linux/tick_trace.h"

namespace {

// The recording's line that declares the SYNC period (config/recording_format.h).
std::string sync_period_line(const planter::config::BoardConfig& board) {
  return std::string(planter::config::kSyncPeriodKey) + ": " +
         planter::config::sync_period_value(board.controller.can.sync_period_ns);
}

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
  std::string pairing_secret_file = "/var/lib/planterd/pairing-secret";
  std::string console_audit_log = "/var/lib/planterd/console-audit.log";
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

// The row as planted, beside the recording; false when it could not be written.
bool write_as_planted(const daemon::AsPlantedLog& log, const std::string& record) {
  const std::string path = daemon::as_planted_path(record);
  std::string why;
  if (!log.write(path, why)) {
    std::fprintf(stderr, "planterd: %s: %s\n", path.c_str(), why.c_str());
    return false;
  }
  std::fprintf(stderr,
               "planterd: as planted: %zu seedlings placed by GNSS, %zu seen with no fix, in %s\n",
               log.placed(), log.unplaced(), path.c_str());
  return true;
}

// One tick of the loop thread: the daemon's requests (stop, fault reset, run), the
// controller's tick, and the hand-off to the recorder and the status readers. Returns false once
// the machine is at rest after a stop.
class LoopTick {
 public:
  LoopTick(const Options& opt, ControlCycle& controller, Shared& shared,
           console::SpscQueue<Row>* rows, hal::linux_backend::TickTrace& trace,
           daemon::BoardHardware& hw, std::int64_t start_ns, std::int64_t overrun_threshold_ns,
           std::int64_t period_ns, console::CommandChannel* commands,
           console::SpscQueue<Row>* console_rows)
      : opt_(opt),
        controller_(controller),
        shared_(shared),
        rows_(rows),
        trace_(trace),
        hw_(hw),
        start_ns_(start_ns),
        loop_start_ns_(monotonic_now_ns()),
        duration_ns_(static_cast<std::int64_t>(opt.duration_s * 1e9)),
        overrun_threshold_ns_(overrun_threshold_ns),
        period_ns_(period_ns),
        commands_(commands),
        console_rows_(console_rows),
        console_every_(console::ticks_per_live_sample(period_ns)) {}

  bool operator()(std::int64_t now, std::int64_t dt, std::int64_t late_ns) {
    trace_.begin(now, late_ns, dt);
    // After a link-loss reset (firmware/supervisor/link_recovery.h) the run is asked for again.
    if (controller_.link_resets() != link_resets_seen_) {
      link_resets_seen_ = controller_.link_resets();
      shared_.link_resets.store(link_resets_seen_, std::memory_order_relaxed);
      run_requested_ = false;
    }
    if (duration_ns_ > 0 && now - loop_start_ns_ >= duration_ns_) shared_.stop = true;
    if (shared_.stop && stop_at_ns_ < 0) {
      controller_.request_stop();
      stop_at_ns_ = now;
    }
    if (shared_.fault_reset.exchange(false)) controller_.request_fault_reset();
    if (opt_.run && !run_requested_ && controller_.state() == SupervisorState::kReady &&
        shared_.commissioned.load(std::memory_order_relaxed)) {
      controller_.request_run();
      run_requested_ = true;
    }
    // The commissioning gate: an operator's run is refused while the stamp does not match.
    controller_.set_run_gate(shared_.commissioned.load(std::memory_order_relaxed));
    // The console's commands, answered by the supervisor's rules (no allocation, no wait).
    if (commands_ != nullptr) {
      commands_->serve([&](const console::ConsoleRequest& request, console::ConsoleReply& reply) {
        reply.t_s = static_cast<double>(now - start_ns_) * 1e-9;
        console::answer_with(controller_, request, reply);
      });
    }
    controller_.tick(now, dt);
    hw_.edge_latency().tick_done(monotonic_now_ns());
    const Telemetry& t = controller_.telemetry();
    if (rows_ != nullptr && !rows_->push(Row{static_cast<double>(now - start_ns_) * 1e-9, t}))
      shared_.rows_dropped.fetch_add(1, std::memory_order_relaxed);
    // The console's samples (console/live_sample.h); a full queue drops one.
    if (console_rows_ != nullptr && ++console_tick_ % console_every_ == 0)
      console_rows_->push(Row{static_cast<double>(now - start_ns_) * 1e-9, t});
    if (shared_.status_mutex.try_lock()) {
      shared_.status = t;
      shared_.status_mutex.unlock();
    }
    trace_.phase_done(hal::TickPhase::kHandOff);
    // An overrun as the supervisor counts it: every one must be explainable from the log.
    if (dt > overrun_threshold_ns_ || late_ns >= period_ns_) trace_.capture_overrun();
    shared_.ticks.fetch_add(1, std::memory_order_release);
    if (stop_at_ns_ < 0) return true;
    // Safe stop: the drives are brought to rest by the controller; leave once they are.
    const SupervisorState s = controller_.state();
    const bool at_rest = s != SupervisorState::kRunning && s != SupervisorState::kStopping;
    return !(at_rest || now - stop_at_ns_ > kStopGraceNs);
  }

 private:
  static constexpr std::int64_t kStopGraceNs = 5'000'000'000;
  const Options& opt_;
  ControlCycle& controller_;
  Shared& shared_;
  console::SpscQueue<Row>* rows_;
  hal::linux_backend::TickTrace& trace_;
  daemon::BoardHardware& hw_;
  std::int64_t start_ns_, loop_start_ns_, duration_ns_, overrun_threshold_ns_, period_ns_;
  console::CommandChannel* commands_;
  console::SpscQueue<Row>* console_rows_;
  std::int64_t console_every_;
  std::int64_t console_tick_ = 0;
  std::int64_t stop_at_ns_ = -1;
  bool run_requested_ = false;
  std::uint32_t link_resets_seen_ = 0;
};

// The main thread, once per flush period: signals, the recording's flush, overrun reports,
// the commissioning stamp, the watchdog and the status log. It reaches the loop only through
// Shared and the row queue.
class MainThread {
 public:
  MainThread(const Options& opt, Shared& shared, daemon::ServiceNotifier& service,
             daemon::CrashSafeRecording* recording, daemon::ConsoleRecording* console_recording,
             daemon::AsPlantedLog* as_planted, console::SpscQueue<Row>& rows,
             hal::linux_backend::TickTrace& trace, daemon::BoardHardware& hw)
      : opt_(opt),
        shared_(shared),
        service_(service),
        recording_(recording),
        console_recording_(console_recording),
        as_planted_(as_planted),
        rows_(rows),
        trace_(trace),
        hw_(hw),
        watchdog_(service.watchdog_enabled(watchdog_us_)),
        next_log_ns_(monotonic_now_ns()),
        next_kick_ns_(monotonic_now_ns()) {}

  void wake(const sigset_t& signals) {
    timespec wait{};
    wait.tv_nsec = static_cast<long>(opt_.flush_ms) * 1'000'000 % 1'000'000'000;
    wait.tv_sec = opt_.flush_ms / 1000;
    const int sig = sigtimedwait(&signals, nullptr, &wait);
    if (sig == SIGTERM || sig == SIGINT) {
      if (!shared_.stop) std::fprintf(stderr, "planterd: %s: stopping safely\n", strsignal(sig));
      shared_.stop = true;
      service_.notify("STOPPING=1");
    } else if (sig == SIGUSR1) {
      shared_.fault_reset = true;
    }
    if (recording_ != nullptr) {
      take_rows();
      if (!recording_->flush() && recording_ok_) {
        std::fprintf(stderr, "planterd: %s: write failed; recording stopped\n",
                     opt_.record.c_str());
        recording_ok_ = false;
      }
      if (console_recording_ != nullptr) console_recording_->flush();
    }
    if (const std::string overrun = trace_.take_report(); !overrun.empty()) {
      std::fprintf(stderr, "planterd: %s", overrun.c_str());
    }
    Telemetry status;
    {
      std::lock_guard<std::mutex> lock(shared_.status_mutex);
      status = shared_.status;
    }
    const std::int64_t now = monotonic_now_ns();
    if (!opt_.commissioned_stamp.empty() && now >= next_stamp_check_ns_) check_stamp(now);
    // Feed the watchdog only while the control loop makes progress.
    const std::uint64_t ticks = shared_.ticks.load(std::memory_order_acquire);
    if (watchdog_ && now >= next_kick_ns_ && ticks != ticks_at_last_kick_) {
      service_.notify("WATCHDOG=1");
      ticks_at_last_kick_ = ticks;
      next_kick_ns_ = now + static_cast<std::int64_t>(watchdog_us_) * 1000 / 2;
    }
    if (status.state != logged_state_) {
      std::fprintf(stderr, "planterd: %s -> %s (faults 0x%x)\n",
                   supervisor_state_name(logged_state_), supervisor_state_name(status.state),
                   status.faults);
      service_.notify(std::string("STATUS=") + supervisor_state_name(status.state));
      logged_state_ = status.state;
    }
    // Each alarm as it rises and clears, named as the console names it.
    for (int bit = 0; bit < warning::kCount; ++bit) {
      const std::uint32_t mask = 1u << bit;
      if ((status.warnings & mask) == (logged_warnings_ & mask)) continue;
      std::fprintf(stderr, "planterd: alarm %s: %s\n",
                   (status.warnings & mask) != 0 ? "raised" : "cleared", warning::name(bit));
    }
    logged_warnings_ = status.warnings;
    if (opt_.log_period_s > 0 && now >= next_log_ns_) {
      log_status(status, hw_.can().counters());
      next_log_ns_ = now + static_cast<std::int64_t>(opt_.log_period_s * 1e9);
    }
  }

  // After the loop ended: the last rows; true when the recording was written whole.
  bool drain() {
    if (recording_ == nullptr) return true;
    take_rows();
    return recording_->flush() && recording_ok_;
  }

 private:
  void take_rows() {
    Row row{};
    while (rows_.pop(row)) {
      if (!recording_->add(row.t_s, row.telemetry) && recording_->rows_unformatted() == 1)
        std::fprintf(stderr,
                     "planterd: %s: a row at %.3f s is longer than a line may be and is not "
                     "recorded (the count is in the last line)\n",
                     opt_.record.c_str(), row.t_s);
      if (console_recording_ != nullptr) console_recording_->add(row.t_s, row.telemetry);
      if (as_planted_ != nullptr) as_planted_->add(row.telemetry);
    }
  }

  // Looked at once a second, so a check that passes lets the drives start without a restart.
  void check_stamp(std::int64_t now) {
    std::string why;
    const bool ok = config::commissioned(opt_.commissioned_stamp, opt_.board, why);
    shared_.commissioned = ok;
    if (!ok && why != not_commissioned_logged_) {
      std::fprintf(stderr, "planterd: drives stay off: %s\n", why.c_str());
      service_.notify("STATUS=not commissioned: " + why);
    } else if (ok && !not_commissioned_logged_.empty()) {
      std::fprintf(stderr, "planterd: commissioning stamp %s matches the board\n",
                   opt_.commissioned_stamp.c_str());
    }
    not_commissioned_logged_ = ok ? "" : why;
    next_stamp_check_ns_ = now + 1'000'000'000;
  }

  const Options& opt_;
  Shared& shared_;
  daemon::ServiceNotifier& service_;
  daemon::CrashSafeRecording* recording_;
  daemon::ConsoleRecording* console_recording_;
  daemon::AsPlantedLog* as_planted_;
  console::SpscQueue<Row>& rows_;
  hal::linux_backend::TickTrace& trace_;
  daemon::BoardHardware& hw_;
  std::uint64_t watchdog_us_ = 0;
  bool watchdog_;
  std::uint64_t ticks_at_last_kick_ = 0;
  std::int64_t next_log_ns_;
  std::int64_t next_kick_ns_;
  std::int64_t next_stamp_check_ns_ = 0;
  SupervisorState logged_state_ = SupervisorState::kBoot;
  std::uint32_t logged_warnings_ = 0;
  std::string not_commissioned_logged_;
  bool recording_ok_ = true;
};

// The operator's console on the board's [console] port, served from its own threads. Without
// the pairing secret's file it is for viewing only, and says so.
class OperatorConsole {
 public:
#ifdef PLANTERD_WITH_CONSOLE
  OperatorConsole(const config::BoardConfig& board, const Options& opt,
                  console::CommandChannel& commands) {
    console::ConsoleOptions o;
    o.loop_cpu = board.realtime.cpu;
    o.bind = board.console.bind;
    o.port = board.console.port;
    o.secrets.viewer = board.console.viewer_secret;
    std::string secret;
    try {
      secret = console::OperatorSessions::read_secret_file(opt.pairing_secret_file);
    } catch (const config::ConfigError& e) {
      std::fprintf(stderr, "planterd: console: viewing only: no pairing secret (%s)\n", e.what());
    }
    if (!secret.empty()) {
      o.secrets.pairing = secret;
      o.commands = &commands;
      o.audit_log = opt.console_audit_log;
    }
    // The console's recordings go beside --record's, from the same rows.
    if (!opt.record.empty()) {
      o.recordings_dir = std::filesystem::path(opt.record).parent_path().string();
      if (o.recordings_dir.empty()) o.recordings_dir = ".";
      recording_ = std::make_unique<daemon::ConsoleRecording>(
          o.recordings_dir,
          std::vector<std::string>{"board: " + board.name, "source: planterd console",
                                   "units: PRODUCT.md v1", sync_period_line(board)});
      if (o.commands != nullptr) o.recording = recording_.get();
    }
    server_ = std::make_unique<console::ConsoleServer>(
        o, console::console_info(board.name, board.controller, false));
    server_->start();
    std::fprintf(stderr, "planterd: console on http://%s:%d/ (%s; audit log %s)\n",
                 console::url_host(o.bind).c_str(), server_->port(),
                 o.commands != nullptr ? "commands with the pairing secret" : "viewing only",
                 o.commands != nullptr ? o.audit_log.c_str() : "none");
  }
  [[nodiscard]] daemon::ConsoleRecording* recording() { return recording_.get(); }
  // The main thread: the loop's samples since the last call, to the console.
  void publish(console::SpscQueue<Row>& rows) {
    Row row{};
    while (rows.pop(row)) server_->publish(console::live_sample(row.t_s, row.telemetry));
  }

 private:
  std::unique_ptr<daemon::ConsoleRecording> recording_;  // before the server: it outlives it
  std::unique_ptr<console::ConsoleServer> server_;
#else
  OperatorConsole(const config::BoardConfig& board, const Options&, console::CommandChannel&) {
    std::fprintf(stderr,
                 "planterd: warning: %s sets a console port, but this build has no console "
                 "(built without cpp-httplib)\n",
                 board.file.c_str());
  }
  void publish(console::SpscQueue<Row>& rows) {
    Row row{};
    while (rows.pop(row)) {
    }
  }
  [[nodiscard]] daemon::ConsoleRecording* recording() { return nullptr; }
#endif
};

// The command line; -1 to go on, else the exit code (--help: 0, a bad option: 2).
int parse_options(int argc, char** argv, Options& opt) {
  CLI::App app{"planterd: the scallion transplanter's controller daemon"};
  app.set_version_flag("--version", std::string("planterd ") + planter::apps::version());
  planter::apps::add_list_keys_flag(app, planter::config::kBoardFileKeys,
                                    "the board, machine and calibration files");
  app.add_option("--board", opt.board, "board file (boards/<board>/board.toml)")->required();
  app.add_option("--record", opt.record, "record telemetry to this CSV (docs/recording-format.md)");
  app.add_flag("--run", opt.run, "start planting as soon as every node is ready (unattended)");
  app.add_option("--duration", opt.duration_s, "stop safely after this many seconds (tests)")
      ->check(planter::config::finite_range(0.0, 1e7));
  app.add_option("--flush-ms", opt.flush_ms, "recording flush interval: the most a crash loses")
      ->check(planter::config::finite_range(10, 10000));
  app.add_option("--log-period", opt.log_period_s, "status line every N seconds (0 = off)")
      ->check(planter::config::finite_range(0.0, 3600.0));
  app.add_flag("--resume-after-link-loss", opt.resume_after_link_loss,
               "after the CAN link went down and came back, reset the faults it caused and boot "
               "the nodes again (with --run: plant again)");
  app.add_option("--commissioned-stamp", opt.commissioned_stamp,
                 "start the drives (--run) only while this stamp from `planter-can check "
                 "--mark-commissioned` matches the board file");
  app.add_option("--pairing-secret-file", opt.pairing_secret_file,
                 "the console's operator pairing secret (the package makes it at installation)")
      ->capture_default_str();
  app.add_option("--console-audit-log", opt.console_audit_log,
                 "every console login and command is appended here")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return planter::apps::parse_ended(app, e, "planterd", argc, argv, 2);
  }
  return -1;
}

// What planterd opens before its loop: the board, its hardware and the crash-safe recording.
struct Opened {
  config::BoardConfig board;
  std::unique_ptr<daemon::BoardHardware> hw;
  std::unique_ptr<daemon::CrashSafeRecording> recording;
};

// The wall clock at the start, as the recording's metadata line that places row times on it.
std::string start_wall_line() {
  timespec start_wall{};
  clock_gettime(CLOCK_REALTIME, &start_wall);
  char text[64];
  std::snprintf(text, sizeof text, "start_wall: %lld.%06ld",
                static_cast<long long>(start_wall.tv_sec), start_wall.tv_nsec / 1000);
  return text;
}

// Opens them, or returns the exit code of a failure said on stderr (-1: opened).
int open_board(const Options& opt, Opened& o) {
  const std::string start_wall = start_wall_line();
  try {
    o.board = config::load_board(opt.board);
    for (const auto& w : o.board.warnings)
      std::fprintf(stderr, "planterd: warning: %s\n", w.c_str());
    o.hw = std::make_unique<daemon::BoardHardware>(o.board);
    if (!opt.record.empty()) {
      o.recording = std::make_unique<daemon::CrashSafeRecording>(
          opt.record,
          std::vector<std::string>{"board: " + o.board.name, "source: planterd",
                                   "units: PRODUCT.md v1", sync_period_line(o.board),
                                   "flush_ms: " + std::to_string(opt.flush_ms), start_wall});
      if (!o.recording->moved_aside_to().empty())
        std::fprintf(stderr, "planterd: previous recording moved to %s\n",
                     o.recording->moved_aside_to().c_str());
    }
  } catch (const config::ConfigError& e) {
    return fail(2, e.what());
  } catch (const hal::linux_backend::HalError& e) {
    return fail(2, std::string(o.board.file) + ": " + e.what());
  } catch (const std::exception& e) {
    return fail(2, e.what());
  }
  std::fprintf(stderr, "planterd: %s\n",
               config::clamp_ceiling_derivation(o.board.clamp_ceiling,
                                                o.board.controller.clamp.stem.reference_diameter_mm)
                   .c_str());
  return -1;
}

// Signals are taken by the main thread only (sigtimedwait), never by the loop thread.
sigset_t block_signals() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGUSR1);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  return signals;
}

hal::linux_backend::RtLoopConfig rt_loop_config(const config::BoardConfig& board) {
  hal::linux_backend::RtLoopConfig rt;
  rt.period_ns = board.controller.can.sync_period_ns;
  rt.priority = board.realtime.priority;
  rt.cpu = board.realtime.cpu;
  rt.require_realtime = board.realtime.require;
  return rt;
}

// The last lines: the encoder-edge latency, and the state, loop and bus figures at the stop.
void print_stop_summary(const ControlCycle& controller, const hal::linux_backend::RtLoop& loop,
                        daemon::BoardHardware& hw, const Shared& shared,
                        const daemon::CrashSafeRecording* recording) {
  const auto& lat = loop.latency();
  const auto& edge = hw.edge_latency().histogram();
  std::fprintf(stderr,
               "planterd: encoder edge to CAN command: %llu edges, p50 %.0f us p99 %.0f us max "
               "%.0f us\n",
               static_cast<unsigned long long>(edge.count()), edge.percentile_us(50),
               edge.percentile_us(99), edge.max_us());
  const hal::CanBusCounters can = hw.can().counters();
  std::fprintf(
      stderr,
      "planterd: stopped in %s after %llu ticks; wake-up latency p50 %.0f us p99 %.0f "
      "us max %.0f us; overruns %llu; CAN link downs %u reopens %u, error frames %u, "
      "tx dropped %u, rx overflow %u; unknown frames %u; rows dropped %llu; link-loss resets "
      "%u\n",
      supervisor_state_name(controller.state()), static_cast<unsigned long long>(loop.ticks()),
      lat.percentile_us(50), lat.percentile_us(99), lat.max_us(),
      static_cast<unsigned long long>(loop.overruns()), hw.can().link_down_count(),
      hw.can().reopen_count(), can.error_frames, can.tx_dropped, can.rx_overflow,
      controller.telemetry().unknown_frames,
      static_cast<unsigned long long>(shared.rows_dropped.load() +
                                      (recording ? recording->rows_unformatted() : 0)),
      shared.link_resets.load());
}
}  // namespace

int main(int argc, char** argv) {
  Options opt;
  if (const int code = parse_options(argc, argv, opt); code >= 0) return code;
  // Row times count from here; start_wall in the metadata places them on the wall clock.
  const std::int64_t start_ns = monotonic_now_ns();
  Opened opened;
  if (const int code = open_board(opt, opened); code >= 0) return code;
  const config::BoardConfig& board = opened.board;
  daemon::BoardHardware& hw = *opened.hw;
  daemon::CrashSafeRecording* recording = opened.recording.get();
  const sigset_t signals = block_signals();

  hal::linux_backend::TickTrace trace;  // per-tick phase times, dumped on an overrun
  hw.controller_hal().tick_probe = &trace;
  ControllerConfig controller_config = board.controller;
  controller_config.link_recovery.enabled = opt.resume_after_link_loss;
  controller_config.link_recovery.resume_running = opt.run;
  ControlCycle controller(controller_config, hw.controller_hal());
  console::SpscQueue<Row> rows(4096);
  Shared shared;
  if (!opt.commissioned_stamp.empty()) {
    std::string why;
    shared.commissioned = config::commissioned(opt.commissioned_stamp, opt.board, why);
  }
  console::CommandChannel commands;
  console::SpscQueue<Row> console_rows(64);
  std::unique_ptr<OperatorConsole> operator_console;
  if (board.console.port > 0) {
    try {
      operator_console = std::make_unique<OperatorConsole>(board, opt, commands);
    } catch (const std::exception& e) {
      return fail(2, e.what());
    }
  }
  const hal::linux_backend::RtLoopConfig rt_config = rt_loop_config(board);
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
    LoopTick tick(opt, controller, shared, recording ? &rows : nullptr, trace, hw, start_ns,
                  board.controller.supervisor.overrun_threshold_ns, rt_config.period_ns,
                  operator_console ? &commands : nullptr,
                  operator_console ? &console_rows : nullptr);
    loop.run([&](std::int64_t now, std::int64_t dt) { return tick(now, dt, loop.last_late_ns()); });
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

  // A board with a receiver maps the row beside the recording (apps/planterd/as_planted_log.h).
  std::unique_ptr<daemon::AsPlantedLog> as_planted;
  if (recording && board.gnss.receiver != "none")
    as_planted = std::make_unique<daemon::AsPlantedLog>(board);
  MainThread main_thread(opt, shared, service, recording,
                         operator_console ? operator_console->recording() : nullptr,
                         as_planted.get(), rows, trace, hw);
  while (!shared.finished) {
    main_thread.wake(signals);
    if (operator_console) operator_console->publish(console_rows);
  }
  loop_thread.join();
  const bool recording_ok = main_thread.drain();
  const bool map_ok = !as_planted || write_as_planted(*as_planted, opt.record);
  operator_console.reset();  // after the last rows: its recording takes them too
  print_stop_summary(controller, loop, hw, shared, recording);
  return recording_ok && map_ok ? 0 : 1;
}
