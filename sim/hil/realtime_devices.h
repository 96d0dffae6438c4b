#pragma once
// `planter-sim devices`: the plant and its CANopen nodes in real time on a real bus and real
// GPIO lines, so an unmodified planterd can run against them (host-in-the-loop). One thread:
// epoll on the CAN socket and a 1 ms timerfd; every millisecond the devices answer and the
// plant advances, and encoder edges become gpio-sim line changes.
#include <atomic>
#include <string>

#include "sim/runner/scenario.h"

namespace planter::sim {

struct RealtimeDevicesOptions {
  std::string can_interface;
  std::string gpio_chip;
  std::string truth_path;   // ground truth CSV, every 10 ms; empty = none
  double duration_s = 0.0;  // 0 = until the route's end plus the scenario's tail
};

struct RealtimeDevicesResult {
  double seconds = 0.0;
  double distance_m = 0.0;
  int seedlings_planted = 0;
  std::uint64_t frames_in = 0, frames_out = 0, frames_lost = 0;
  unsigned gpio_writes = 0;
  std::uint32_t link_downs = 0, reopens = 0;
  std::uint64_t late_steps = 0;  // plant steps taken late by more than 5 ms
};

// Throws HalError (bad interface or chip) or ConfigError.
RealtimeDevicesResult run_realtime_devices(const Scenario& scenario,
                                           const RealtimeDevicesOptions& options,
                                           const std::atomic<bool>& stop);

}  // namespace planter::sim
