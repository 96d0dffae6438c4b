#pragma once
// The operator's console over HTTP, served from its own threads (a fixed pool, with the bounds of
// guarded_server.h around cpp-httplib's parsing), never
// from the control loop: the loop publishes a LiveSample into a lock-free queue of fixed size
// (no lock, no allocation, a full queue drops the sample and counts it); the server's threads
// drain it into the history the page plots. Commands go the other way through a
// CommandChannel, which the loop serves once a tick; who may give them is OperatorSessions'
// rule (operator_sessions.h), and each one is written to the AuditLog.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "console/audit_log.h"
#include "console/command_channel.h"
#include "console/connection_limits.h"
#include "console/host_names.h"
#include "console/live_sample.h"
#include "console/operator_sessions.h"
#include "console/recording_control.h"
#include "console/refused_logins.h"
#include "console/spsc_queue.h"
#include "firmware/controller/setpoint_rules.h"

namespace httplib {
class Server;
struct Request;
struct Response;
}  // namespace httplib

namespace planter::console {

class GuardedServer;

struct ConsoleOptions {
  std::string bind = "127.0.0.1";  // the machine's network: 0.0.0.0
  int port = 8080;                 // 0: any free port (port() says which)
  std::size_t history = 3000;      // samples kept for the plots (5 min at 10 Hz)
  // Commands: all three are needed, or the console is for viewing only.
  CommandChannel* commands = nullptr;
  std::string audit_log;  // path
  Secrets secrets;
  SessionPolicy policy;
  std::string recordings_dir;             // recordings offered for download; empty: none
  RecordingControl* recording = nullptr;  // record_start and record_stop; nullptr: refused
  // Names besides the machine's own (host name, addresses, localhost) a browser may reach it
  // by, as in Host: a name given in the farm's DNS, say.
  std::vector<std::string> host_names;
  // The control loop's CPU (-1: none pinned). The console's threads keep off it, and never run
  // at the real-time priority of whatever thread starts the console (issue 30, item 4).
  int loop_cpu = -1;
};

// What the page shows beside the live values: the machine and its limits.
struct ConsoleInfo {
  std::string title;  // scenario or board name
  double clamp_ceiling_N = 0.0;
  double target_spacing_mm = 0.0;
  double row_spacing_mm = 0.0;
  double spacing_cv_alarm = 0.0;
  double singulation_alarm_pct = 0.0;
  double disc_top_speed_mps = 0.0;  // the fastest the disc holds sigma at
  bool photo_eye = false;
  bool simulated = false;  // sigma_true is known
  SetpointRange depth_range_mm;
  SetpointRange clamp_force_range_N;
};

// The machine's limits as its controller configuration sets them (setpoint_rules.h).
inline ConsoleInfo console_info(std::string title, const ControllerConfig& c, bool simulated) {
  ConsoleInfo info;
  info.title = std::move(title);
  info.clamp_ceiling_N = c.clamp.ceiling_N;
  info.target_spacing_mm = c.monitor.target_spacing_mm;
  info.row_spacing_mm = c.monitor.row_spacing_mm;
  info.spacing_cv_alarm = c.monitor.spacing_cv_alarm;
  info.singulation_alarm_pct = c.monitor.singulation_alarm_pct;
  info.disc_top_speed_mps = SigmaLoop(c.sigma).top_ground_speed_mps();
  info.photo_eye = c.monitor.sensor_fitted;
  info.simulated = simulated;
  info.depth_range_mm = depth_range_mm(c);
  info.clamp_force_range_N = clamp_force_range_N(c);
  return info;
}

// The calling thread leaves the loop's CPU (if one is pinned, and another exists) and any
// real-time policy it inherited; the threads it makes from then (the connection workers) inherit
// that. The console's threads call it first; so may any other helper of the loop's program.
void leave_the_loop(int loop_cpu);

class ConsoleServer {
 public:
  ConsoleServer(const ConsoleOptions& options, const ConsoleInfo& info);
  ~ConsoleServer();
  ConsoleServer(const ConsoleServer&) = delete;
  ConsoleServer& operator=(const ConsoleServer&) = delete;

  // Binds and starts serving; throws std::runtime_error naming the address or the file when it
  // cannot.
  void start();
  void stop();
  [[nodiscard]] int port() const { return port_; }
  [[nodiscard]] bool takes_commands() const { return options_.commands != nullptr; }

  // The loop's side: no lock, no allocation. False (and counted) when the queue is full.
  bool publish(const LiveSample& sample);
  [[nodiscard]] std::uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  void drain();  // the server's threads: queue -> history
  std::string state_json();
  std::string history_json();
  void install_command_routes(httplib::Server& srv);
  void install_recording_routes(httplib::Server& srv);
  // The caller's session, or an answer (401) already written into res.
  bool may_view(const httplib::Request& req, httplib::Response& res);
  void command(const httplib::Request& req, httplib::Response& res);
  void login(const httplib::Request& req, httplib::Response& res);
  // One audit line, after the summary of the refused logins not yet said; false when the log
  // cannot be written.
  bool audit(const std::string& address, const std::string& session, const std::string& what,
             const std::string& value, const std::string& result);
  // Writes a refused login's line or summary (if there is an audit log).
  void audit_refusals(const std::optional<RefusalSummary>& s);

  ConsoleOptions options_;
  ConsoleInfo info_;
  std::string page_;
  SpscQueue<LiveSample> queue_;
  std::atomic<std::uint64_t> dropped_{0};
  std::mutex history_mutex_;  // the one consumer of queue_, and the history
  std::deque<LiveSample> history_;
  std::unique_ptr<OperatorSessions> sessions_;
  std::unique_ptr<AuditLog> audit_;
  std::mutex host_names_mutex_;
  HostNames host_names_;
  RefusedLoginTally refused_logins_{60.0};  // one summary line a minute at most
  // Who may hold a connection (guarded_server.h); a slot taken from an idle one is cut there.
  ConnectionLimits limits_;
  std::unique_ptr<GuardedServer> server_;
  std::thread thread_;
  // Moves the loop's samples into the history five times a second whether or not anyone is
  // looking (issue 28, item 6: with no client the queue filled and new samples were dropped).
  std::thread drainer_;
  std::mutex drainer_mutex_;
  std::condition_variable drainer_wake_;
  bool drainer_stop_ = false;
  int port_ = 0;
};

}  // namespace planter::console
