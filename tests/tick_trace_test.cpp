// planterd's tick trace: phases stamped in order, one snapshot per overrun until the log has
// taken it, and a report that names the counts that tell the program's stalls from the
// machine's.
#include "hal/linux/tick_trace.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "hal/linux/monotonic_clock.h"

namespace planter::hal::linux_backend {
namespace {

TEST(TickTrace, StampsPhasesAndReportsOneSnapshotPerOverrun) {
  TickTrace trace;
  EXPECT_EQ(trace.take_report(), "");  // nothing captured yet
  std::int64_t wake = monotonic_now_ns();
  for (int k = 0; k < 40; ++k) {
    trace.begin(wake, 50'000, 10'000'000);
    for (int p = 0; p < kTickPhaseCount; ++p) trace.phase_done(static_cast<TickPhase>(p));
    wake += 10'000'000;
  }
  const auto& t = trace.current();
  for (int p = 1; p < kTickPhaseCount; ++p) EXPECT_GE(t.phase_end_ns[p], t.phase_end_ns[p - 1]);
  // A stall of the program's own making: touching fresh memory pages faults them in.
  std::vector<char> fresh(64 << 20);
  for (std::size_t i = 0; i < fresh.size(); i += 4096) fresh[i] = 1;
  trace.begin(wake + 30'000'000, 30'000'000, 40'000'000);
  ASSERT_TRUE(trace.capture_overrun());
  EXPECT_FALSE(trace.capture_overrun());  // the first is still waiting for the log
  const std::string report = trace.take_report();
  EXPECT_NE(report.find("page faults: the program's"), std::string::npos) << report;
  EXPECT_NE(report.find("late  30.000 dt  40.000"), std::string::npos) << report;
  // Ring of 32: the oldest line is 31 ticks before the overrun.
  std::size_t lines = 0;
  for (const char c : report) lines += c == '\n';
  EXPECT_EQ(lines, 2u + TickTrace::kTicks);
  EXPECT_EQ(trace.take_report(), "");
  EXPECT_TRUE(trace.capture_overrun());  // taken: the next overrun is captured again
  EXPECT_EQ(trace.overruns_captured(), 2u);
}

}  // namespace
}  // namespace planter::hal::linux_backend
