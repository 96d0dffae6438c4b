// Proves the control tick allocates nothing after init: a counting global operator new
// around the controller's ticks, with the runner, devices and plant stepping as usual.
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "sim/runner/lockstep_runner.h"

namespace {
std::atomic<bool> counting{false};
std::atomic<unsigned long long> allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SCENARIO.toml\n", argv[0]);
    return 2;
  }
  auto scenario = planter::sim::load_scenario(argv[1]);
  scenario.plant.route.distance_m = 3.0;
  planter::sim::LockstepRunner runner(scenario);
  // Init: boot and commissioning, then well into the run.
  while (runner.time_s() < 10.0) runner.step();
  if (runner.controller().state() != planter::SupervisorState::kRunning) {
    std::fprintf(stderr, "controller did not reach running\n");
    return 1;
  }
  // Ticks of the controller alone, driven by the runner's clock and bus.
  const int ticks = 20000;
  unsigned long long controller_allocs = 0, step_allocs = 0;
  for (int i = 0; i < ticks; ++i) {
    counting = true;
    const auto before = allocations.load();
    runner.step();  // controller tick + devices + plant sub-steps
    counting = false;
    step_allocs += allocations.load() - before;
  }
  // The controller's own tick, isolated: same state, tick called directly.
  const std::int64_t now = static_cast<std::int64_t>(runner.time_s() * 1e9);
  for (int i = 0; i < ticks; ++i) {
    counting = true;
    const auto before = allocations.load();
    runner.controller().tick(now + static_cast<std::int64_t>(i) * 10'000'000, 10'000'000);
    counting = false;
    controller_allocs += allocations.load() - before;
  }
  std::printf(
      "whole lockstep step (controller + bus + devices + plant): %.3f allocations per tick over %d "
      "ticks\n",
      static_cast<double>(step_allocs) / ticks, ticks);
  std::printf("heap allocations per control tick after init: %.3f (%llu in %d ticks; goal 0)\n",
              static_cast<double>(controller_allocs) / ticks, controller_allocs, ticks);
  return controller_allocs == 0 ? 0 : 1;
}
