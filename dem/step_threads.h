#pragma once
// Threads that share a DEM step's per-pair work: each runs its own part (a range of the bonds
// and of the candidate pairs), the caller runs part 0, and run() returns when every part is
// done. Which thread runs a part does not change its results (each pair writes only its own
// outputs), so a world gives the same bits on any number of threads.
// The threads live as long as the pool and wait between steps (a short spin, then yielding
// the core, then C++20's atomic wait), so a step costs no thread start and, on an idle
// machine, no wake-up. On a busy one more threads can be slower than one (measured: 1.3x
// slower with one core taken by another process): `--threads 1` then.
#include <atomic>
#include <thread>
#include <vector>

namespace planter::dem {

class StepThreads {
 public:
  explicit StepThreads(int threads);
  // A copy has threads of its own (a copied world steps apart from its original).
  StepThreads(const StepThreads& other) : StepThreads(other.threads()) {}
  StepThreads& operator=(const StepThreads&) = delete;
  ~StepThreads();

  [[nodiscard]] int threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Runs part(k) for k in [0, threads()): k = 0 on the calling thread.
  template <typename Part>
  void run(Part& part) {
    if (workers_.empty()) {
      part(0);
      return;
    }
    call_ = [](void* p, int k) { (*static_cast<Part*>(p))(k); };
    context_ = &part;
    start_and_wait();
  }

 private:
  void start_and_wait();
  void work(int part);

  std::vector<std::thread> workers_;
  void (*call_)(void*, int) = nullptr;
  void* context_ = nullptr;
  std::atomic<unsigned> generation_{0};
  std::atomic<int> pending_{0};
  std::atomic<bool> stopping_{false};
};

}  // namespace planter::dem
