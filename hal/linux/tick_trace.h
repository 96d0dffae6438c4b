#pragma once
// Per-tick timing of planterd's loop in a fixed ring: when the tick woke (and how late), and
// when each phase ended (hal::TickProbe). On an overrun the loop thread copies the ring and the
// thread's page-fault and context-switch counts (getrusage) into a snapshot, without
// allocating; the service thread formats it for the log. A stall with page faults or with no
// involuntary switch is the program's; one with involuntary switches and nothing else slow is
// the machine taking the CPU away.
#include <array>
#include <atomic>
#include <cstdint>
#include <string>

#include "planter/hal/tick_probe.h"

namespace planter::hal::linux_backend {

class TickTrace final : public TickProbe {
 public:
  static constexpr std::size_t kTicks = 32;
  struct Tick {
    std::int64_t wake_ns = 0;                                  // CLOCK_MONOTONIC at wake-up
    std::int64_t late_ns = 0;                                  // how late the wake-up was
    std::int64_t dt_ns = 0;                                    // since the previous tick
    std::array<std::int64_t, kTickPhaseCount> phase_end_ns{};  // 0 = phase not reached
  };
  struct Usage {
    long minor_faults = 0, major_faults = 0, voluntary_switches = 0, involuntary_switches = 0;
  };

  // Loop thread, real-time: no allocation, no lock.
  void begin(std::int64_t wake_ns, std::int64_t late_ns, std::int64_t dt_ns);
  void phase_done(TickPhase phase) override;
  // Copies the ring (oldest first) and the usage counts, unless an earlier snapshot is still
  // waiting for the log; returns whether it was taken.
  bool capture_overrun();
  // Service thread: the waiting snapshot as log lines, or "" when there is none.
  std::string take_report();

  [[nodiscard]] const Tick& current() const { return ring_[head_]; }
  [[nodiscard]] std::uint64_t overruns_captured() const { return captured_; }

 private:
  static Usage thread_usage();
  std::array<Tick, kTicks> ring_{};
  std::size_t head_ = 0;
  bool started_ = false;
  std::array<Tick, kTicks> snapshot_{};
  Usage usage_{}, usage_before_{}, last_usage_{};
  std::atomic<int> state_{0};  // 0 empty, 1 being written, 2 ready, 3 being read
  std::uint64_t captured_ = 0;
};

}  // namespace planter::hal::linux_backend
