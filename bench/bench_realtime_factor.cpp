// Lockstep real-time factor of the field scenario on one core: the firmware controller, the
// CANopen frames on the virtual bus, the devices and the plant, without file output.
// Prints the median of three runs last.
#include <algorithm>
#include <cstdio>
#include <vector>

#include "sim/runner/lockstep_runner.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SCENARIO.toml\n", argv[0]);
    return 2;
  }
  const auto scenario = planter::sim::load_scenario(argv[1]);
  std::vector<double> factors;
  double sim_s = 0;
  unsigned long long frames = 0;
  for (int i = 0; i < 3; ++i) {
    planter::sim::LockstepRunner runner(scenario);
    const auto s = runner.run();
    factors.push_back(s.realtime_factor);
    sim_s = s.sim_seconds;
    frames = s.can_frames;
    std::printf("run %d: %.1f s simulated in %.3f s wall, %llu CAN frames\n", i + 1, s.sim_seconds,
                s.wall_seconds, frames);
  }
  std::sort(factors.begin(), factors.end());
  std::printf(
      "lockstep real-time factor (%s, %.0f s, %llu frames): %.0fx real time (goal >= 2000x)\n",
      scenario.name.c_str(), sim_s, frames, factors[1]);
  return 0;
}
