#pragma once
// A GNSS receiver through gpsd (Debian's gpsd and libgps): a thread of its own watches gpsd's
// reports (?WATCH, JSON) and hands each fix to the controller through a GnssMailbox, so the
// real-time loop never waits on a socket. gpsd absent, or stopping mid-run, is a receiver
// not connected (the ground fusion falls back to the wheel and says so); it is tried again
// every second.
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <thread>

#include "planter/hal/gnss.h"

struct gps_data_t;

namespace planter::hal::linux_backend {

struct GpsdOptions {
  std::string host = "127.0.0.1";
  int port = 2947;
  // From the fix's measurement to its report reaching us (assumed; receivers: tens of ms to
  // 0.1 s). The fix is dated its arrival less this, on the controller's clock.
  std::int64_t latency_ns = 50'000'000;
};

// When a gpsd report says its fix was measured, in seconds of the receiver's (UTC) clock.
double fix_time_s(const gps_data_t& data);

// One gpsd report as a fix: `arrival_ns` is when it came (the controller's clock), `previous`
// the last fix made (its time stands still when the receiver's does). Pure, for the tests.
GnssFix fix_from_gpsd(const gps_data_t& data, std::int64_t arrival_ns, const GnssFix& previous,
                      double previous_time_s, std::int64_t latency_ns);

class GpsdReceiver final : public GnssSource {
 public:
  // `now_ns` is the controller's clock (CLOCK_MONOTONIC on a board).
  GpsdReceiver(GpsdOptions options, std::function<std::int64_t()> now_ns);
  ~GpsdReceiver() override;
  GpsdReceiver(const GpsdReceiver&) = delete;
  GpsdReceiver& operator=(const GpsdReceiver&) = delete;

  bool latest(GnssFix& fix) override { return box_.get(fix); }
  [[nodiscard]] bool connected() const override { return connected_.load(); }
  // Reports read since start, and connections made (for logs and tests).
  [[nodiscard]] std::uint64_t reports() const { return reports_.load(); }
  [[nodiscard]] std::uint64_t connections() const { return connections_.load(); }

 private:
  void run();
  void watch(gps_data_t& data, GnssFix& last, double& last_time_s);

  GpsdOptions options_;
  std::function<std::int64_t()> now_ns_;
  GnssMailbox box_;
  std::atomic<bool> connected_{false};
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> reports_{0}, connections_{0};
  std::thread thread_;
};

}  // namespace planter::hal::linux_backend
