#pragma once
// The real-time loop of planterd: SCHED_FIFO at a configured priority and CPU, memory locked,
// stack and heap pre-faulted, periodic wake-ups by clock_nanosleep(TIMER_ABSTIME) on
// CLOCK_MONOTONIC, and a record of how late each wake-up was (the same measure cyclictest
// takes) plus the periods that were missed entirely (overruns).
#include <time.h>

#include <array>
#include <cstdint>
#include <string>

#include "hal/linux/monotonic_clock.h"

namespace planter::hal::linux_backend {

struct RtLoopConfig {
  std::int64_t period_ns = 10'000'000;
  int priority = 80;  // SCHED_FIFO priority, 1-99; 0 = ordinary scheduling
  int cpu = -1;       // pin to this CPU; -1 = any
  std::size_t prefault_stack_bytes = 512 * 1024;
  std::size_t prefault_heap_bytes = 8 * 1024 * 1024;
  bool require_realtime = false;  // fail instead of warn when SCHED_FIFO or mlockall is refused
};

// Wake-up latency distribution in 1 us bins (fixed memory: filled from the loop).
class LatencyHistogram {
 public:
  static constexpr std::size_t kBins = 20000;  // up to 20 ms; later ones land in the last bin
  void add(std::int64_t latency_ns);
  [[nodiscard]] std::uint64_t count() const { return count_; }
  [[nodiscard]] double percentile_us(double p) const;
  [[nodiscard]] double max_us() const { return static_cast<double>(max_ns_) * 1e-3; }
  [[nodiscard]] double mean_us() const;

 private:
  std::array<std::uint32_t, kBins> bins_{};
  std::uint64_t count_ = 0;
  std::int64_t max_ns_ = 0;
  double sum_ns_ = 0.0;
};

class RtLoop {
 public:
  explicit RtLoop(const RtLoopConfig& config) : config_(config) {}
  ~RtLoop();
  RtLoop(const RtLoop&) = delete;
  RtLoop& operator=(const RtLoop&) = delete;

  // Applies scheduling, affinity, mlockall and pre-faulting. Returns "" on success, else what
  // was refused; throws HalError instead when require_realtime is set.
  std::string setup();

  // Calls tick(now_ns, dt_ns) once per period until it returns false. A wake-up later than
  // one whole period counts as an overrun and the schedule skips ahead instead of bursting.
  template <typename Tick>
  void run(Tick&& tick) {
    timespec next{};
    clock_gettime(CLOCK_MONOTONIC, &next);
    std::int64_t next_ns = timespec_ns(next);
    std::int64_t previous_ns = next_ns - config_.period_ns;
    for (;;) {
      next_ns += config_.period_ns;
      next = from_ns(next_ns);
      while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr) != 0) {
      }
      const std::int64_t now = monotonic_now_ns();
      const std::int64_t late = now - next_ns;
      latency_.add(late);
      last_late_ns_ = late;
      if (late >= config_.period_ns) {
        ++overruns_;
        next_ns += (late / config_.period_ns) * config_.period_ns;
      }
      ++ticks_;
      const std::int64_t dt = now - previous_ns;
      previous_ns = now;
      if (!tick(now, dt)) return;
    }
  }

  [[nodiscard]] const LatencyHistogram& latency() const { return latency_; }
  [[nodiscard]] std::uint64_t overruns() const { return overruns_; }
  [[nodiscard]] std::uint64_t ticks() const { return ticks_; }
  // How late the current tick's wake-up was.
  [[nodiscard]] std::int64_t last_late_ns() const { return last_late_ns_; }
  [[nodiscard]] const RtLoopConfig& config() const { return config_; }

 private:
  static timespec from_ns(std::int64_t ns) {
    timespec t{};
    t.tv_sec = static_cast<time_t>(ns / 1'000'000'000);
    t.tv_nsec = static_cast<long>(ns % 1'000'000'000);
    return t;
  }

  RtLoopConfig config_;
  LatencyHistogram latency_;
  std::uint64_t overruns_ = 0;
  std::uint64_t ticks_ = 0;
  std::int64_t last_late_ns_ = 0;
  int dma_latency_fd_ = -1;
};

}  // namespace planter::hal::linux_backend
