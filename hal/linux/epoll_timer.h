#pragma once
// One thread waiting on a periodic timerfd and a set of file descriptors with epoll: wakes
// when the period elapses or when any watched descriptor (a CAN socket) becomes readable.
#include <cstdint>

namespace planter::hal::linux_backend {

class EpollTimer {
 public:
  explicit EpollTimer(std::int64_t period_ns);  // throws HalError
  ~EpollTimer();
  EpollTimer(const EpollTimer&) = delete;
  EpollTimer& operator=(const EpollTimer&) = delete;

  // Watches fd for input (replacing any earlier watch of the same fd). -1 is ignored.
  void watch(int fd);
  void unwatch(int fd);
  // Blocks until the timer fires or a watched fd is readable. Returns how many periods
  // elapsed since the last call (0 = woken by a descriptor only).
  std::uint64_t wait();

 private:
  int epoll_fd_ = -1;
  int timer_fd_ = -1;
};

}  // namespace planter::hal::linux_backend
