#include "sim/runner/run_many.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

#include "sim/runner/lockstep_runner.h"

namespace planter::sim {

std::vector<Summary> run_many(const std::vector<Scenario>& scenarios, int jobs,
                              const std::string& label) {
  std::vector<Summary> out(scenarios.size());
  std::atomic<std::size_t> next{0}, done{0};
  const bool show = !label.empty() && ::isatty(STDERR_FILENO) == 1;
  std::mutex show_mutex;
  const auto finished = [&] {
    const std::size_t n = ++done;
    if (!show) return;
    const std::lock_guard<std::mutex> lock(show_mutex);
    std::fprintf(stderr, "\r%s: %zu of %zu runs", label.c_str(), n, scenarios.size());
    if (n == scenarios.size()) std::fprintf(stderr, "\n");
  };
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < scenarios.size(); i = next++) {
      try {
        LockstepRunner runner(scenarios[i]);
        out[i] = runner.run();
        finished();
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  return out;
}

}  // namespace planter::sim
