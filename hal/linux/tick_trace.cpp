#include "hal/linux/tick_trace.h"

#include <sys/resource.h>

#include <cstdio>

#include "hal/linux/monotonic_clock.h"

namespace planter::hal::linux_backend {

namespace {
double ms(std::int64_t ns) { return static_cast<double>(ns) * 1e-6; }
}  // namespace

TickTrace::Usage TickTrace::thread_usage() {
  rusage ru{};
  getrusage(RUSAGE_THREAD, &ru);
  return {ru.ru_minflt, ru.ru_majflt, ru.ru_nvcsw, ru.ru_nivcsw};
}

void TickTrace::begin(std::int64_t wake_ns, std::int64_t late_ns, std::int64_t dt_ns) {
  if (!started_) {
    last_usage_ = thread_usage();  // counts from here on are the loop's
    started_ = true;
  }
  head_ = (head_ + 1) % kTicks;
  ring_[head_] = Tick{wake_ns, late_ns, dt_ns, {}};
}

void TickTrace::phase_done(TickPhase phase) {
  ring_[head_].phase_end_ns[static_cast<std::size_t>(phase)] = monotonic_now_ns();
}

bool TickTrace::capture_overrun() {
  int expected = 0;
  if (!state_.compare_exchange_strong(expected, 1, std::memory_order_acquire)) return false;
  for (std::size_t i = 0; i < kTicks; ++i) snapshot_[i] = ring_[(head_ + 1 + i) % kTicks];
  usage_before_ = last_usage_;
  usage_ = thread_usage();
  last_usage_ = usage_;
  ++captured_;
  state_.store(2, std::memory_order_release);
  return true;
}

std::string TickTrace::take_report() {
  int expected = 2;
  if (!state_.compare_exchange_strong(expected, 3, std::memory_order_acquire)) return "";
  const Usage d{usage_.minor_faults - usage_before_.minor_faults,
                usage_.major_faults - usage_before_.major_faults,
                usage_.voluntary_switches - usage_before_.voluntary_switches,
                usage_.involuntary_switches - usage_before_.involuntary_switches};
  char line[256];
  std::snprintf(line, sizeof line,
                "overrun: the loop thread since the previous report: %ld minor and %ld major "
                "page faults, %ld voluntary and %ld involuntary context switches (%s)\n",
                d.minor_faults, d.major_faults, d.voluntary_switches, d.involuntary_switches,
                d.major_faults + d.minor_faults > 0 ? "page faults: the program's"
                : d.involuntary_switches > 0        ? "preempted: the machine's"
                                                    : "neither: a slow phase or a late timer");
  std::string out = line;
  out +=
      "overrun: last ticks (ms after the first wake-up: wake, late; phase ends receive, "
      "control, transmit, hand-off as ms after wake)\n";
  const std::int64_t t0 = snapshot_[0].wake_ns;
  for (const Tick& t : snapshot_) {
    if (t.wake_ns == 0) continue;
    std::snprintf(line, sizeof line, "  %9.3f late %7.3f dt %7.3f |", ms(t.wake_ns - t0),
                  ms(t.late_ns), ms(t.dt_ns));
    out += line;
    for (const std::int64_t end : t.phase_end_ns) {
      std::snprintf(line, sizeof line, end > 0 ? " %7.3f" : "       -",
                    end > 0 ? ms(end - t.wake_ns) : 0.0);
      out += line;
    }
    out += "\n";
  }
  state_.store(0, std::memory_order_release);
  return out;
}

}  // namespace planter::hal::linux_backend
