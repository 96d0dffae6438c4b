#pragma once
// A FIFO whose storage is allocated once, at construction; push and pop never allocate.
#include <cstddef>
#include <vector>

namespace planter {

template <typename T>
class FixedRing {
 public:
  explicit FixedRing(std::size_t capacity) : slots_(capacity) {}

  bool push(const T& value) {
    if (size_ == slots_.size()) return false;
    slots_[(head_ + size_) % slots_.size()] = value;
    ++size_;
    return true;
  }
  bool pop(T& out) {
    if (size_ == 0) return false;
    out = slots_[head_];
    head_ = (head_ + 1) % slots_.size();
    --size_;
    return true;
  }
  void clear() { head_ = size_ = 0; }
  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] bool empty() const { return size_ == 0; }
  [[nodiscard]] std::size_t capacity() const { return slots_.size(); }

 private:
  std::vector<T> slots_;
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

}  // namespace planter
