#pragma once
// The operator's console over HTTP, served from its own threads (cpp-httplib's pool), never
// from the control loop: the loop publishes a LiveSample into a lock-free queue of fixed size
// (no lock, no allocation, a full queue drops the sample and counts it); the server's threads
// drain it into the history the page plots. Viewing only, for now: it takes no command.
#include <atomic>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "console/live_sample.h"
#include "console/spsc_queue.h"

namespace httplib {
class Server;
}

namespace planter::console {

struct ConsoleOptions {
  std::string bind = "127.0.0.1";  // the machine's network: 0.0.0.0
  int port = 8080;                 // 0: any free port (port() says which)
  std::size_t history = 3000;      // samples kept for the plots (5 min at 10 Hz)
};

// What the page shows beside the live values: the machine and its limits.
struct ConsoleInfo {
  std::string title;  // scenario or board name
  double clamp_ceiling_N = 0.0;
  double target_spacing_mm = 0.0;
  bool photo_eye = false;
  bool simulated = false;  // sigma_true is known
};

class ConsoleServer {
 public:
  ConsoleServer(const ConsoleOptions& options, const ConsoleInfo& info);
  ~ConsoleServer();
  ConsoleServer(const ConsoleServer&) = delete;
  ConsoleServer& operator=(const ConsoleServer&) = delete;

  // Binds and starts serving; throws std::runtime_error naming the address when it cannot.
  void start();
  void stop();
  [[nodiscard]] int port() const { return port_; }

  // The loop's side: no lock, no allocation. False (and counted) when the queue is full.
  bool publish(const LiveSample& sample);
  [[nodiscard]] std::uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  void drain();  // the server's threads: queue -> history
  std::string state_json();
  std::string history_json();

  ConsoleOptions options_;
  ConsoleInfo info_;
  std::string page_;
  SpscQueue<LiveSample> queue_;
  std::atomic<std::uint64_t> dropped_{0};
  std::mutex history_mutex_;  // the one consumer of queue_, and the history
  std::deque<LiveSample> history_;
  std::unique_ptr<httplib::Server> server_;
  std::thread thread_;
  int port_ = 0;
};

}  // namespace planter::console
