// Wake-up latency of planterd's real-time loop against Debian's cyclictest, at the same time on
// two CPUs (ours on CPU 0, cyclictest on CPU 1; same period, priority and duration), so a stall
// of the machine shows in both and one of the program shows in ours alone. Each tick of our
// loop does a full lockstep step (controller, devices, plant) as its work, traced per tick
// (hal/linux/tick_trace.h): the first overrun prints the ticks before it and the page-fault and
// context-switch counts. Prints the p50/p99/max of both, whose the worst wake-up was, and last
// the ratio of the p99s (goal: <= 1.2) and the overruns.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hal/linux/rt_loop.h"
#include "hal/linux/tick_trace.h"
#include "sim/runner/lockstep_runner.h"

using namespace planter;

namespace {

struct Stats {
  double p50 = 0, p99 = 0, max = 0;
};

// cyclictest --histfile: one line per microsecond bin, "bin count" (comments start with #).
Stats cyclictest_stats(const std::string& histfile, double max_us) {
  std::ifstream in(histfile);
  std::vector<std::pair<int, long>> bins;
  long total = 0;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    int bin = 0;
    long count = 0;
    if (ss >> bin >> count) {
      bins.emplace_back(bin, count);
      total += count;
    }
  }
  Stats s;
  s.max = max_us;
  long seen = 0;
  for (const auto& [bin, count] : bins) {
    seen += count;
    if (s.p50 == 0 && seen * 100 >= total * 50) s.p50 = bin + 1;
    if (s.p99 == 0 && seen * 100 >= total * 99) s.p99 = bin + 1;
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: planter_bench_latency SCENARIO [seconds=60] [priority=80]\n");
    return 2;
  }
  const double seconds = argc > 2 ? std::atof(argv[2]) : 60.0;
  const int priority = argc > 3 ? std::atoi(argv[3]) : 80;
  const sim::Scenario scenario = sim::load_scenario(argv[1]);
  const std::int64_t period_ns = scenario.board.controller.can.sync_period_ns;
  const long loops = static_cast<long>(seconds * 1e9 / static_cast<double>(period_ns));

  // 1. cyclictest in the background on CPU 1, for as many wake-ups as our loop makes.
  const std::string hist = "/tmp/planter_bench_cyclictest.hist";
  const std::string cmd = "cyclictest -q -m -p " + std::to_string(priority) + " -a 1 -t 1 -i " +
                          std::to_string(period_ns / 1000) + " -l " + std::to_string(loops) +
                          " -h 20000 --histfile=" + hist + " > /tmp/planter_bench_cyclictest.out";
  const pid_t cyclictest = fork();
  if (cyclictest == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // 2. Our loop (the same RtLoop planterd runs) on CPU 0, at the same time.
  hal::linux_backend::RtLoopConfig cfg;
  cfg.period_ns = period_ns;
  cfg.priority = priority;
  cfg.cpu = 0;
  hal::linux_backend::RtLoop loop(cfg);
  sim::LockstepRunner runner(scenario);
  const std::string refused = loop.setup();
  if (!refused.empty()) std::printf("warning: %s\n", refused.c_str());
  hal::linux_backend::TickTrace trace;  // keeps the first overrun's ticks for after the run
  long n = 0;
  loop.run([&](std::int64_t now, std::int64_t dt) {
    trace.begin(now, loop.last_late_ns(), dt);
    runner.step();
    trace.phase_done(hal::TickPhase::kHandOff);
    if (loop.last_late_ns() >= period_ns) trace.capture_overrun();
    return ++n < loops;
  });
  const auto& h = loop.latency();
  Stats ours{h.percentile_us(50), h.percentile_us(99), h.max_us()};
  std::printf(
      "planterd loop : %ld wake-ups at %.0f Hz, SCHED_FIFO %d on CPU 0: p50 %.0f us, p99 "
      "%.0f us, max %.0f us, overruns %llu\n",
      n, 1e9 / static_cast<double>(period_ns), priority, ours.p50, ours.p99, ours.max,
      static_cast<unsigned long long>(loop.overruns()));
  // Formatted after the run, as planterd's service thread does: no string is built in the loop.
  if (const std::string report = trace.take_report(); !report.empty())
    std::printf("first %s", report.c_str());
  sched_param normal{};
  sched_setscheduler(0, SCHED_OTHER, &normal);
  int rc = 0;
  waitpid(cyclictest, &rc, 0);
  if (!WIFEXITED(rc) || WEXITSTATUS(rc) != 0) {
    std::printf("cyclictest failed (exit %d); is rt-tests installed?\n", WEXITSTATUS(rc));
    return 1;
  }
  double ct_max = 0;
  {
    std::ifstream out(hist);
    std::string line;
    while (std::getline(out, line))
      if (line.rfind("# Max Latencies:", 0) == 0) ct_max = std::atof(line.c_str() + 16);
  }
  const Stats ct = cyclictest_stats(hist, ct_max);
  if (ct.p99 <= 0) {
    std::printf("cyclictest wrote no histogram to %s\n", hist.c_str());
    return 1;
  }
  std::printf(
      "cyclictest    : %ld wake-ups at the same time on CPU 1, same period and priority: p50 "
      "%.0f us, p99 %.0f us, max %.0f us\n",
      loops, ct.p50, ct.p99, ct.max);
  // A wake-up over a millisecond late in ours while cyclictest's worst stayed under half of
  // it is our program's; when both saw one, the machine stalled both CPUs.
  const bool ours_stalled = ours.max > 1000.0;
  std::printf("worst wake-up: ours %.0f us, cyclictest %.0f us in the same window: %s\n", ours.max,
              ct.max,
              !ours_stalled              ? "no stall"
              : ct.max >= 0.5 * ours.max ? "the machine's (both CPUs late)"
                                         : "the program's (ours alone late)");
  std::printf("p99 wake-up latency ratio planterd/cyclictest: %.2f (goal <= 1.2), overruns %llu\n",
              ct.p99 > 0 ? ours.p99 / ct.p99 : 0.0,
              static_cast<unsigned long long>(loop.overruns()));
  return 0;
}
