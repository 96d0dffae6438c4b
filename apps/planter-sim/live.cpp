#include "apps/planter-sim/live.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "config/output_set.h"
#include "config/recording_format.h"
#include "console/client_address.h"
#include "console/operator_sessions.h"
#include "plan/folder_lock.h"
#include "sim/runner/lockstep_runner.h"
#include "sim/runner/recording_writer.h"
#include "sim/runner/summary.h"

namespace planter::sim {
namespace {
std::atomic<bool> g_stop{false};  // set by SIGINT/SIGTERM: the only way a signal can talk
extern "C" void on_signal(int) { g_stop.store(true); }

// The console's recordings: started and stopped by the operator (from the console's thread),
// one file each, written by the simulation's thread and flushed five times a second, so a
// download or a reader sees the last 0.2 s.
class LiveRecorder : public console::RecordingControl {
 public:
  LiveRecorder(std::string dir, const Scenario& scenario)
      : dir_(std::move(dir)), scenario_(scenario) {}

  console::ConsoleReply start() override {
    std::lock_guard<std::mutex> lock(mutex_);
    if (writer_)
      return console::recording_reply(console::ConsoleResult::kRefused,
                                      "already recording to " + name_);
    const std::string name = console::recording_file_name("live");
    const std::string path = dir_ + "/" + name;
    try {
      writer_ = std::make_unique<RecordingWriter>(
          path, path,
          std::vector<std::pair<std::string, std::string>>{
              {"source", "planter-sim live"},
              {"scenario", scenario_.name},
              {"board", scenario_.board.name},
              {"units", "1"},
              {std::string(config::kSyncPeriodKey),
               config::sync_period_value(scenario_.board.controller.can.sync_period_ns)}});
    } catch (const std::exception& e) {
      return console::recording_reply(console::ConsoleResult::kFailed, e.what());
    }
    // The metadata and header must reach the disk before "accepted" is said.
    if (!writer_->flush()) {
      writer_.reset();
      std::remove(path.c_str());
      return console::recording_reply(console::ConsoleResult::kFailed,
                                      name + " cannot be written (is the disk full?)");
    }
    name_ = name;
    failed_.clear();
    return console::recording_reply(console::ConsoleResult::kAccepted, "recording to " + name_);
  }

  console::ConsoleReply stop() override {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!writer_ && !failed_.empty()) {  // it stopped by itself: say why, once
      const std::string words = failed_;
      failed_.clear();
      return console::recording_reply(console::ConsoleResult::kFailed, words);
    }
    if (!writer_)
      return console::recording_reply(console::ConsoleResult::kRefused, "not recording");
    try {
      auto writer = std::move(writer_);
      writer->close();
    } catch (const std::exception& e) {
      return console::recording_reply(console::ConsoleResult::kFailed, e.what());
    }
    return console::recording_reply(console::ConsoleResult::kAccepted,
                                    "recording " + name_ + " closed");
  }

  std::string active() override {
    std::lock_guard<std::mutex> lock(mutex_);
    return writer_ ? name_ : std::string();
  }

  void write(const TickRecord& r) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!writer_) return;
    try {
      writer_->write(r);
    } catch (const std::exception& e) {
      fail(e.what());
    }
  }

  // A recording that can no longer be written stops, and says so.
  void flush() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (writer_ && !writer_->flush()) fail("cannot be written (is the disk full?)");
  }

 private:
  std::string dir_;
  const Scenario& scenario_;
  std::mutex mutex_;  // the console's thread starts and stops; the simulation's writes
  // Under mutex_: the recording stops, its file is set aside as cut, and stop() says why.
  void fail(const std::string& why) {
    writer_.reset();
    failed_ = console::set_aside_cut(dir_, name_, why);
    std::fprintf(stderr, "planter-sim live: %s\n", failed_.c_str());
  }

  std::unique_ptr<RecordingWriter> writer_;
  std::string name_;
  std::string failed_;  // a recording that stopped by itself, until stop() says it
};

}  // namespace

int run_live(const std::string& scenario_path, const LiveOptions& options) {
  Scenario scenario = load_scenario(scenario_path);
  // A person at the console starts the machine, as on one just powered; with no operator's
  // controls (--view-only) the scenario's own operator does.
  scenario.operator_presses_run = options.view_only;
  const ControllerConfig& cfg = scenario.board.controller;
  const console::ConsoleInfo info =
      console::console_info(scenario.name + " (simulated)", cfg, true);

  console::ConsoleOptions console_options = options.console;
  console::CommandChannel commands;
  const std::string recordings = options.dir + "/recordings";
  LiveRecorder recorder(recordings, scenario);
  std::string pairing;
  std::optional<plan::FolderLock> lock;
  if (!options.view_only) {
    config::make_directories(recordings);
    // One live instance per --dir: two would share the audit log and the recordings.
    lock.emplace(options.dir, "another planter-sim live uses this directory (--dir another)");
    pairing = options.pairing_secret_file.empty()
                  ? console::OperatorSessions::new_secret()
                  : console::OperatorSessions::read_secret_file(options.pairing_secret_file);
    console_options.commands = &commands;
    console_options.audit_log = options.dir + "/audit.log";
    console_options.secrets.pairing = pairing;
    console_options.recordings_dir = recordings;
    console_options.recording = &recorder;
  }
  if (!options.viewer_secret_file.empty())
    console_options.secrets.viewer =
        console::OperatorSessions::read_secret_file(options.viewer_secret_file);
  console::ConsoleServer server(console_options, info);
  server.start();
  std::printf("console: http://%s:%d/  (%s; Ctrl-C to stop)\n",
              console::url_host(options.console.bind).c_str(), server.port(),
              scenario.name.c_str());
  if (!options.view_only) {
    // The terminal is this machine's screen: the secret is shown here, and nowhere else.
    if (options.pairing_secret_file.empty())
      std::printf("console: operator pairing secret %s (new for this run)\n", pairing.c_str());
    std::printf("console: recordings in %s, audit log %s\n", recordings.c_str(),
                console_options.audit_log.c_str());
    std::printf("console: the machine waits for Start (log in as the operator and press it)\n");
  }
  std::fflush(stdout);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);

  LockstepRunner runner(scenario);
  const std::int64_t every = console::ticks_per_live_sample(cfg.can.sync_period_ns);
  std::int64_t tick = 0;
  runner.set_observer([&](const TickRecord& r) {
    recorder.write(r);
    if (++tick % every != 0) return;
    console::LiveSample s =
        console::live_sample(static_cast<double>(r.controller.time_ns) * 1e-9, r.controller);
    // The true sigma where the machine moves fast enough for it to mean something.
    s.sigma_true = r.truth.v_mps >= kSigmaMinSpeedMps ? r.truth.sigma
                                                      : std::numeric_limits<double>::quiet_NaN();
    server.publish(s);
  });
  const auto start = std::chrono::steady_clock::now();
  auto next_flush = start;
  while (!g_stop.load()) {
    // The operator's commands, between two ticks, as planterd's loop takes them.
    commands.serve([&](const console::ConsoleRequest& request, console::ConsoleReply& reply) {
      reply.t_s = runner.time_s();
      console::answer_with(runner.controller(), request, reply);
    });
    runner.step();
    const double t = runner.time_s();
    if (options.duration_s > 0.0 && t >= options.duration_s) break;
    const auto now = std::chrono::steady_clock::now();
    if (now >= next_flush) {
      recorder.flush();
      next_flush = now + std::chrono::milliseconds(200);
    }
    std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::nanoseconds>(
                                              std::chrono::duration<double>(t / options.speed)));
  }
  server.stop();
  const console::ConsoleReply closing = recorder.stop();
  if (closing.result == console::ConsoleResult::kFailed) {
    std::fprintf(stderr, "planter-sim live: %s\n", closing.text);
    return 1;
  }
  std::printf("console: stopped at %.1f s simulated\n", runner.time_s());
  return 0;
}

}  // namespace planter::sim
