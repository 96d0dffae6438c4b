#include "dem/step_threads.h"

#include <algorithm>

namespace planter::dem {
namespace {

// Waits for `a` to leave `old`: spinning first (a step's serial part is tens of microseconds,
// a futex wake-up on a virtual machine as long), yielding the core after a short while (a busy
// machine's other work, or this world's own threads on fewer cores, may need it to get here),
// then blocking (a world no longer stepping costs no core).
template <typename T>
void spin_then_wait(const std::atomic<T>& a, T old) {
  for (int k = 0; k < 4000; ++k) {
    if (a.load() != old) return;
    if (k < 200) {
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    } else {
      std::this_thread::yield();
    }
  }
  a.wait(old);
}

}  // namespace

StepThreads::StepThreads(int threads) {
  for (int k = 1; k < std::max(1, threads); ++k) workers_.emplace_back([this, k] { work(k); });
}

StepThreads::~StepThreads() {
  stopping_.store(true);
  generation_.fetch_add(1);
  generation_.notify_all();
  for (auto& t : workers_) t.join();
}

void StepThreads::start_and_wait() {
  pending_.store(static_cast<int>(workers_.size()));
  generation_.fetch_add(1);  // publishes call_ and context_ (sequentially consistent)
  generation_.notify_all();
  call_(context_, 0);
  for (int left = pending_.load(); left != 0; left = pending_.load())
    spin_then_wait(pending_, left);
}

void StepThreads::work(int part) {
  unsigned seen = 0;
  while (true) {
    spin_then_wait(generation_, seen);
    seen = generation_.load();
    if (stopping_.load()) return;
    call_(context_, part);
    if (pending_.fetch_sub(1) == 1) pending_.notify_one();
  }
}

}  // namespace planter::dem
