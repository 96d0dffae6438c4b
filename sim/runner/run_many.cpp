#include "sim/runner/run_many.h"

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "sim/runner/lockstep_runner.h"

namespace planter::sim {

std::vector<Summary> run_many(const std::vector<Scenario>& scenarios, int jobs) {
  std::vector<Summary> out(scenarios.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < scenarios.size(); i = next++) {
      try {
        LockstepRunner runner(scenarios[i]);
        out[i] = runner.run();
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
