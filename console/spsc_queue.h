#pragma once
// A single-producer single-consumer queue of fixed capacity: the real-time loop pushes without
// locks or allocation, another thread pops. A full queue refuses the push (counted by caller).
#include <atomic>
#include <cstddef>
#include <memory>

namespace planter::console {

template <typename T>
class SpscQueue {
 public:
  explicit SpscQueue(std::size_t capacity)
      : capacity_(capacity + 1), items_(std::make_unique<T[]>(capacity + 1)) {}

  bool push(const T& item) {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    const std::size_t next = (head + 1) % capacity_;
    if (next == tail_.load(std::memory_order_acquire)) return false;
    items_[head] = item;
    head_.store(next, std::memory_order_release);
    return true;
  }

  bool pop(T& item) {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return false;
    item = items_[tail];
    tail_.store((tail + 1) % capacity_, std::memory_order_release);
    return true;
  }

 private:
  std::size_t capacity_;
  std::unique_ptr<T[]> items_;
  alignas(64) std::atomic<std::size_t> head_{0};
  alignas(64) std::atomic<std::size_t> tail_{0};
};

}  // namespace planter::console
