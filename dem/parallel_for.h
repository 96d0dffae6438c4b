#pragma once
// Runs fn(0) .. fn(count - 1) on up to `jobs` threads (the calling one included). Each index
// runs once; which thread runs it does not change its result, so runs stay deterministic.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace planter::dem {

template <typename Fn>
void parallel_for(std::size_t count, int jobs, Fn&& fn) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t k = next++; k < count; k = next++) fn(k);
  };
  const int threads = std::max(1, std::min<int>(jobs, static_cast<int>(count)));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
}

}  // namespace planter::dem
