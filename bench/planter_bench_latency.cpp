// Wake-up latency of planterd's real-time loop against Debian's cyclictest, at the same time on
// two CPUs (ours on CPU 0, cyclictest on CPU 1; same period, priority and duration), so a stall
// of the machine shows in both and one of the program shows in ours alone. Each tick of our
// loop does a full lockstep step (controller, devices, plant) as its work, traced per tick
// (hal/linux/tick_trace.h): the first overrun prints the ticks before it and the page-fault and
// context-switch counts. Prints the p50/p99/max of both, whose the worst wake-up was, and last
// the ratio of the p99s (goal: <= 1.2) and the overruns.
// Where the build has the console, the loop also does what planterd's does for it (a sample to
// the console ten times a second, the command channel served every tick) while five clients
// poll it as the page does (state at 5 Hz, history every 2 s; one of them logged in and
// setting the depth every 2 s), and a sixth sends 100 wrong secrets as fast as it can a third
// of the way in, while others send endless header lines and hold 100 idle and 8 slow
// connections (issue 28). Windows without the console and with it alternate in rounds (the
// machine is shared and drifts); each counts the loop thread's involuntary context switches and
// the network softirqs on its CPU, and the last line gives the median over the rounds of the
// two windows' ratios to cyclictest: the console's cost, with the machine's noise divided out.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "hal/linux/rt_loop.h"
#include "hal/linux/tick_trace.h"
#include "sim/runner/lockstep_runner.h"
#ifdef PLANTER_BENCH_CONSOLE
#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include "console/console_server.h"
#endif

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

#ifdef PLANTER_BENCH_CONSOLE
// From another loopback address than the clients' (Linux answers all of 127/8): an attacker
// on the farm's network is not the operator's phone.
int connect_loopback(int port, const char* from) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  sockaddr_in src{};
  src.sin_family = AF_INET;
  if (::inet_pton(AF_INET, from, &src.sin_addr) != 1 ||
      ::bind(fd, reinterpret_cast<sockaddr*>(&src), sizeof src) != 0) {
    ::close(fd);
    return -1;
  }
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// Whether the server closed or refused it (readable: an answer or the end); if so, reopened
// and `start` sent. A connection still held open is left as it is.
bool reopen_if_closed(int& fd, int port, const char* from, const std::string& start) {
  if (fd >= 0) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 0) == 0) return false;
    ::close(fd);
  }
  fd = connect_loopback(port, from);
  if (fd >= 0 && !start.empty()) (void)!::send(fd, start.data(), start.size(), MSG_NOSIGNAL);
  return true;
}

// The console's load, as five phones and one guesser would put it on the machine.
class ConsoleLoad {
 public:
  ConsoleLoad(const sim::Scenario& scenario, double seconds, int loop_cpu)
      : every_(console::ticks_per_live_sample(scenario.board.controller.can.sync_period_ns)) {
    console::ConsoleOptions o;
    o.port = 0;
    o.loop_cpu = loop_cpu;
    o.commands = &commands;
    o.audit_log = "/tmp/planter_bench_console_audit.log";
    o.secrets.pairing = console::OperatorSessions::new_secret();
    o.policy.commands_per_window = 1000;  // the depth client is not the one being limited
    server_ = std::make_unique<console::ConsoleServer>(
        o, console::console_info(scenario.name, scenario.board.controller, true));
    server_->start();
    const int port = server_->port();
    const std::string secret = o.secrets.pairing;
    for (int c = 0; c < 5; ++c) {
      clients_.emplace_back([this, port, c, secret, loop_cpu] {
        console::leave_the_loop(loop_cpu);  // phones are not on the machine's loop CPU either
        httplib::Client cli("127.0.0.1", port);
        httplib::Headers operator_headers;
        if (c == 0) {
          auto r = cli.Post("/api/login", "{\"secret\":\"" + secret + "\"}", "application/json");
          if (r && r->status == 200) {
            const std::string cookie = r->get_header_value("Set-Cookie");
            const auto at = r->body.find("\"csrf\":\"");
            operator_headers = {{"Cookie", cookie.substr(0, cookie.find(';'))},
                                {"X-CSRF-Token", r->body.substr(at + 8, 43)}};
          }
        }
        for (int i = 0; !done_; ++i) {
          auto r = cli.Get("/api/state");
          (r && r->status == 200 ? pages : failed)++;
          if (i % 10 == 0) {
            auto h = cli.Get("/api/history");
            (h && h->status == 200 ? pages : failed)++;
            if (c == 0) {
              const std::string depth = i % 20 == 0 ? "95" : "100";
              auto k = cli.Post("/api/command", operator_headers,
                                "{\"command\":\"set_depth_mm\",\"value\":" + depth + "}",
                                "application/json");
              (k && (k->status == 200 || k->status == 409) ? commands_answered : failed)++;
            }
          }
          std::this_thread::sleep_for(std::chrono::milliseconds(200));
        }
      });
    }
    clients_.emplace_back([this, port, seconds] {
      std::this_thread::sleep_for(std::chrono::duration<double>(seconds / 3));
      httplib::Client cli("127.0.0.1", port);
      const auto start = std::chrono::steady_clock::now();
      for (int i = 0; i < 100; ++i) {
        auto r = cli.Post("/api/login", "{\"secret\":\"wrong-" + std::to_string(i) + "\"}",
                          "application/json");
        const int status = r ? r->status : 0;
        (status == 401 ? wrong : status == 429 ? limited : failed)++;
      }
      flood_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    });
    attack(port, loop_cpu);
  }
  // And what anyone on the farm's network can send meanwhile (issue 28): endless header lines,
  // 100 idle connections and 8 slow ones, each reopened when the server closes it.
  void attack(int port, int loop_cpu) {
    clients_.emplace_back([this, port, loop_cpu] {
      console::leave_the_loop(loop_cpu);
      const std::string line = "X-Filler: " + std::string(1000, 'a') + "\r\n";
      while (!done_) {
        const int fd = connect_loopback(port, "127.0.0.2");
        if (fd < 0) continue;
        const std::string start = "GET /api/info HTTP/1.1\r\nHost: 127.0.0.1\r\n";
        bool open = ::send(fd, start.data(), start.size(), MSG_NOSIGNAL) > 0;
        while (open && !done_) open = ::send(fd, line.data(), line.size(), MSG_NOSIGNAL) > 0;
        cut_floods++;
        ::close(fd);
      }
    });
    clients_.emplace_back([this, port, loop_cpu] {
      console::leave_the_loop(loop_cpu);
      std::vector<int> idle(100, -1), slow(8, -1);
      const std::string start = "GET /api/info HTTP/1.1\r\nHost: 127.0.0.1\r\n";
      for (int second = 0; !done_; ++second) {
        for (int& fd : idle) reopen_if_closed(fd, port, "127.0.0.3", "");
        for (int& fd : slow) {
          if (reopen_if_closed(fd, port, "127.0.0.4", start)) continue;
          if (second % 2 == 0) (void)!::send(fd, "X-Slow: 1\r\n", 11, MSG_NOSIGNAL);
        }
        for (int i = 0; i < 10 && !done_; ++i)
          std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
      for (int fd : idle) ::close(fd);
      for (int fd : slow) ::close(fd);
    });
  }
  ~ConsoleLoad() { stop(); }
  void stop() {
    done_ = true;
    for (auto& t : clients_)
      if (t.joinable()) t.join();
    if (server_) server_->stop();
  }
  // The loop's side, as planterd's: no lock, no allocation, no wait.
  void tick(long n, double t_s, sim::LockstepRunner& runner) {
    commands.serve([&](const console::ConsoleRequest& request, console::ConsoleReply& reply) {
      console::answer_with(runner.controller(), request, reply);
    });
    if (n % every_ == 0)
      server_->publish(console::live_sample(t_s, runner.controller().telemetry()));
  }
  [[nodiscard]] std::uint64_t dropped() const { return server_->dropped(); }

  console::CommandChannel commands;
  std::atomic<long> pages{0}, failed{0}, commands_answered{0}, wrong{0}, limited{0};
  std::atomic<double> flood_s{0};
  std::atomic<long> cut_floods{0};

 private:
  std::int64_t every_;  // ticks per console sample, as planterd's
  std::unique_ptr<console::ConsoleServer> server_;
  std::vector<std::thread> clients_;
  std::atomic<bool> done_{false};
};
#endif

#ifdef PLANTER_BENCH_CONSOLE
using LoadOnLoop = ConsoleLoad;
#else
struct LoadOnLoop {  // no console in this build: the loop has nothing more to do
  void tick(long, double, sim::LockstepRunner&) {}
};
#endif

// One window: cyclictest on CPU 1 and our loop on CPU 0 at the same time, for the same number
// of wake-ups, so the machine's own stalls fall on both. With a console load, the loop also
// does the console's part of planterd's tick.
struct Window {
  long wake_ups = 0;
  Stats ours, cyclictest;
  unsigned long long overruns = 0;
  std::string first_overrun;  // the phase trace of the first overrun, if any
  std::string error;          // cyclictest failed
  long preempted = 0;         // the loop thread's involuntary context switches in the window
  long net_softirqs = 0;      // network softirqs run on the loop's CPU in the window
};

// NET_RX + NET_TX softirqs run so far on one CPU (/proc/softirqs): how the console's traffic
// could reach the loop's CPU though none of its threads may run there.
long net_softirqs_on(int cpu) {
  std::ifstream in("/proc/softirqs");
  std::string line;
  long total = 0;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    std::string name;
    ss >> name;
    if (name != "NET_RX:" && name != "NET_TX:") continue;
    long count = 0;
    for (int c = 0; c <= cpu && ss >> count; ++c) {
    }
    total += count;
  }
  return total;
}

long involuntary_switches() {
  rusage u{};
  getrusage(RUSAGE_THREAD, &u);
  return u.ru_nivcsw;
}

Window measure(const sim::Scenario& scenario, const hal::linux_backend::RtLoopConfig& cfg,
               long loops, LoadOnLoop* console_load) {
  Window w;
  const std::string hist = "/tmp/planter_bench_cyclictest.hist";
  const std::string cmd = "cyclictest -q -m -p " + std::to_string(cfg.priority) + " -a 1 -t 1 -i " +
                          std::to_string(cfg.period_ns / 1000) + " -l " + std::to_string(loops) +
                          " -h 20000 --histfile=" + hist + " > /tmp/planter_bench_cyclictest.out";
  const pid_t cyclictest = fork();
  if (cyclictest == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // Our loop (the same RtLoop planterd runs) on CPU 0, at the same time.
  hal::linux_backend::RtLoop loop(cfg);
  sim::LockstepRunner runner(scenario);
  const std::string refused = loop.setup();
  if (!refused.empty()) std::printf("warning: %s\n", refused.c_str());
  hal::linux_backend::TickTrace trace;  // keeps the first overrun's ticks for after the run
  long n = 0;
  const long softirqs_before = net_softirqs_on(cfg.cpu);
  const long switches_before = involuntary_switches();
  loop.run([&](std::int64_t now, std::int64_t dt) {
    trace.begin(now, loop.last_late_ns(), dt);
    if (console_load != nullptr) console_load->tick(n, runner.time_s(), runner);
    runner.step();
    trace.phase_done(hal::TickPhase::kHandOff);
    if (loop.last_late_ns() >= cfg.period_ns) trace.capture_overrun();
    return ++n < loops;
  });
  w.wake_ups = n;
  w.preempted = involuntary_switches() - switches_before;
  w.net_softirqs = net_softirqs_on(cfg.cpu) - softirqs_before;
  const auto& h = loop.latency();
  w.ours = {h.percentile_us(50), h.percentile_us(99), h.max_us()};
  w.overruns = loop.overruns();
  // Formatted after the run, as planterd's service thread does: no string is built in the loop.
  w.first_overrun = trace.take_report();
  sched_param normal{};
  sched_setscheduler(0, SCHED_OTHER, &normal);
  int rc = 0;
  waitpid(cyclictest, &rc, 0);
  if (!WIFEXITED(rc) || WEXITSTATUS(rc) != 0) {
    w.error =
        "cyclictest failed (exit " + std::to_string(WEXITSTATUS(rc)) + "); is rt-tests installed?";
    return w;
  }
  double ct_max = 0;
  {
    std::ifstream out(hist);
    std::string line;
    while (std::getline(out, line))
      if (line.rfind("# Max Latencies:", 0) == 0) ct_max = std::atof(line.c_str() + 16);
  }
  w.cyclictest = cyclictest_stats(hist, ct_max);
  if (w.cyclictest.p99 <= 0) w.error = "cyclictest wrote no histogram to " + hist;
  return w;
}

// Prints a window's two lines and whose its worst wake-up was; false when cyclictest failed.
bool report(const char* name, const Window& w, const hal::linux_backend::RtLoopConfig& cfg) {
  if (!w.error.empty()) {
    std::printf("%s\n", w.error.c_str());
    return false;
  }
  std::printf(
      "%s: planterd loop: %ld wake-ups at %.0f Hz, SCHED_FIFO %d on CPU 0: p50 %.0f us, p99 "
      "%.0f us, max %.0f us, overruns %llu; preempted %ld times, %ld network softirqs on CPU "
      "0\n",
      name, w.wake_ups, 1e9 / static_cast<double>(cfg.period_ns), cfg.priority, w.ours.p50,
      w.ours.p99, w.ours.max, w.overruns, w.preempted, w.net_softirqs);
  std::printf(
      "%s: cyclictest   : the same wake-ups at the same time on CPU 1: p50 %.0f us, p99 %.0f "
      "us, max %.0f us\n",
      name, w.cyclictest.p50, w.cyclictest.p99, w.cyclictest.max);
  if (!w.first_overrun.empty()) std::printf("first %s", w.first_overrun.c_str());
  // A wake-up over a millisecond late in ours while cyclictest's worst stayed under half of
  // it is our program's; when both saw one, the machine stalled both CPUs.
  const bool ours_stalled = w.ours.max > 1000.0;
  std::printf("%s: worst wake-up: ours %.0f us, cyclictest %.0f us in the same window: %s\n", name,
              w.ours.max, w.cyclictest.max,
              !ours_stalled                          ? "no stall"
              : w.cyclictest.max >= 0.5 * w.ours.max ? "the machine's (both CPUs late)"
              : w.preempted == 0 ? "ours alone late, the loop never preempted: its wake-up was "
                                   "delayed below it (kernel or host), not by a thread of ours"
                                 : "the program's (ours alone late, the loop preempted)");
  return true;
}

double p99_ratio(const Window& w) { return w.ours.p99 / w.cyclictest.p99; }

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

  hal::linux_backend::RtLoopConfig cfg;
  cfg.period_ns = period_ns;
  cfg.priority = priority;
  cfg.cpu = 0;
#ifdef PLANTER_BENCH_CONSOLE
  // Rounds of two windows, each a tenth of the time: without the console, then with it, its
  // clients and the attack (started before the measured loop, as in the field). cyclictest
  // runs beside both, so each window's p99 is taken against cyclictest's in the same seconds;
  // alternating windows let the machine's slow drifts fall on both, and the median round
  // keeps one stall of this shared machine from deciding the figure.
  constexpr int kRounds = 5;
  const long window_loops = loops / (2 * kRounds);
  std::vector<double> with_over_without;
  double with_sum = 0, without_sum = 0;
  long preempted_quiet = 0, preempted_busy = 0, softirqs_quiet = 0, softirqs_busy = 0;
  unsigned long long overruns_quiet = 0, overruns_busy = 0;
  for (int round = 1; round <= kRounds; ++round) {
    const std::string quiet_name = "round " + std::to_string(round) + " without console";
    const Window quiet = measure(scenario, cfg, window_loops, nullptr);
    if (!report(quiet_name.c_str(), quiet, cfg)) return 1;
    const double window_s = seconds / (2 * kRounds);
    ConsoleLoad console_load(scenario, window_s, cfg.cpu);
    const Window busy = measure(scenario, cfg, window_loops, &console_load);
    console_load.stop();
    const std::string busy_name = "round " + std::to_string(round) + " with console";
    std::printf(
        "%s: 5 clients for %.0f s: %ld pages served, %ld requests failed, %ld depth commands "
        "answered, %llu samples dropped; 100 wrong secrets in %.2f s: %ld refused (401), %ld "
        "rate-limited (429); under attack meanwhile: %ld header floods cut, 100 idle and 8 slow "
        "connections held\n",
        busy_name.c_str(), window_s, console_load.pages.load(), console_load.failed.load(),
        console_load.commands_answered.load(),
        static_cast<unsigned long long>(console_load.dropped()), console_load.flood_s.load(),
        console_load.wrong.load(), console_load.limited.load(), console_load.cut_floods.load());
    if (!report(busy_name.c_str(), busy, cfg)) return 1;
    with_over_without.push_back(p99_ratio(busy) / p99_ratio(quiet));
    with_sum += p99_ratio(busy);
    without_sum += p99_ratio(quiet);
    preempted_quiet += quiet.preempted;
    preempted_busy += busy.preempted;
    softirqs_quiet += quiet.net_softirqs;
    softirqs_busy += busy.net_softirqs;
    overruns_quiet += quiet.overruns;
    overruns_busy += busy.overruns;
  }
  std::string rounds;
  for (double r : with_over_without) {
    char one[16];
    std::snprintf(one, sizeof one, "%s%.2f", rounds.empty() ? "" : ", ", r);
    rounds += one;
  }
  std::sort(with_over_without.begin(), with_over_without.end());
  std::printf(
      "the loop's thread under the attack: preempted %ld times (%ld without the console), %ld "
      "network softirqs on its CPU (%ld without)\n",
      preempted_busy, preempted_quiet, softirqs_busy, softirqs_quiet);
  std::printf(
      "p99 wake-up latency ratio planterd/cyclictest: %.2f (goal <= 1.2), overruns %llu, with 5 "
      "console clients and the attack; without them %.2f (overruns %llu): with / without median "
      "%.2f of %d rounds (%s) (goal <= 1, no worse)\n",
      with_sum / kRounds, overruns_busy, without_sum / kRounds, overruns_quiet,
      with_over_without[kRounds / 2], kRounds, rounds.c_str());
#else
  std::printf("console: not in this build (no cpp-httplib): measured without clients\n");
  const Window w = measure(scenario, cfg, loops, nullptr);
  if (!report("no console", w, cfg)) return 1;
  std::printf("p99 wake-up latency ratio planterd/cyclictest: %.2f (goal <= 1.2), overruns %llu\n",
              p99_ratio(w), w.overruns);
#endif
  return 0;
}
