// planter-can on the simulated bus: how long a scan of IDs 1-127 takes (bus time, the figure a
// technician waits; goal < 2 s) and how many SDO round trips per second the tool and the
// simulated nodes manage (wall time). Google Benchmark runs the cases; the figures print last.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <sstream>

#include "apps/planter-can/cmd_scan.h"
#include "apps/planter-can/sdo_session.h"
#include "apps/planter-can/sim_link.h"
#include "config/board_config.h"
#include "sim/runner/scenario.h"

namespace {

using namespace planter;

sim::Scenario scenario() {
  sim::Scenario s;
  s.board = config::load_board(PLANTER_SOURCE_DIR "/boards/host-sim/board.toml");
  return s;
}

double g_scan_bus_s = 0.0;
double g_scan_wall_s = 0.0;
double g_sdo_per_s = 0.0;
double g_sdo_bus_per_s = 0.0;

void BM_Scan127(benchmark::State& state) {
  const sim::Scenario s = scenario();
  std::int64_t bus_ns = 0;
  std::int64_t runs = 0;
  for (auto _ : state) {
    cantool::SimLink link(s, {});
    std::ostringstream out, err;
    cantool::ToolContext ctx{link, &s.board, false, out, err, 100'000'000, false};
    const cantool::ScanResult r = cantool::scan_bus(ctx, {});
    if (r.nodes.size() != 4) state.SkipWithError("scan did not find the 4 nodes");
    bus_ns += r.duration_ns;
    ++runs;
  }
  g_scan_bus_s = static_cast<double>(bus_ns) * 1e-9 / static_cast<double>(runs);
  state.counters["bus_s"] = g_scan_bus_s;
}
BENCHMARK(BM_Scan127)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SdoRoundTrip(benchmark::State& state) {
  const sim::Scenario s = scenario();
  cantool::SimLink link(s, {});
  cantool::SdoSession sdo(link, 100'000'000);
  const std::int64_t bus0 = link.now_ns();
  for (auto _ : state) {
    const cantool::SdoResult r = sdo.read(2, 0x1018, 2);
    if (!r.ok()) state.SkipWithError("SDO read failed");
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations());
  g_sdo_bus_per_s =
      static_cast<double>(state.iterations()) / (static_cast<double>(link.now_ns() - bus0) * 1e-9);
}
BENCHMARK(BM_SdoRoundTrip)->UseRealTime();

class Collector : public benchmark::ConsoleReporter {
 public:
  Collector() : benchmark::ConsoleReporter(OO_Tabular) {}  // plain text: CI logs have no colour
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) {
      if (r.benchmark_name().rfind("BM_Scan127", 0) == 0)
        g_scan_wall_s = r.GetAdjustedRealTime() * 1e-3;  // ms -> s
      if (r.benchmark_name().rfind("BM_SdoRoundTrip", 0) == 0) {
        const auto it = r.counters.find("items_per_second");
        if (it != r.counters.end()) g_sdo_per_s = it->second;
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  Collector reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  std::printf(
      "sdo round trips: %.0f per second of wall time (the sim bus answers in one 1 ms "
      "step: %.0f per second of bus time)\n",
      g_sdo_per_s, g_sdo_bus_per_s);
  std::printf(
      "scan of IDs 1-127 on the sim bus: %.3f s of bus time (goal < 2 s: %.2fx under), "
      "%.1f ms of wall time\n",
      g_scan_bus_s, g_scan_bus_s > 0 ? 2.0 / g_scan_bus_s : 0.0, g_scan_wall_s * 1e3);
  return g_scan_bus_s > 0.0 && g_scan_bus_s < 2.0 ? 0 : 1;
}
