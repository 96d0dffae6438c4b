#include "hal/linux/epoll_timer.h"

#include <errno.h>
#include <sys/epoll.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <cstring>
#include <string>

#include "hal/linux/hal_error.h"

namespace planter::hal::linux_backend {

EpollTimer::EpollTimer(std::int64_t period_ns) {
  epoll_fd_ = epoll_create1(EPOLL_CLOEXEC);
  timer_fd_ = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
  if (epoll_fd_ < 0 || timer_fd_ < 0)
    throw HalError(std::string("epoll/timerfd: ") + std::strerror(errno));
  itimerspec spec{};
  spec.it_interval.tv_sec = static_cast<time_t>(period_ns / 1'000'000'000);
  spec.it_interval.tv_nsec = static_cast<long>(period_ns % 1'000'000'000);
  spec.it_value = spec.it_interval;
  timerfd_settime(timer_fd_, 0, &spec, nullptr);
  watch(timer_fd_);
}

EpollTimer::~EpollTimer() {
  if (timer_fd_ >= 0) close(timer_fd_);
  if (epoll_fd_ >= 0) close(epoll_fd_);
}

void EpollTimer::watch(int fd) {
  if (fd < 0) return;
  epoll_event ev{};
  ev.events = EPOLLIN;
  ev.data.fd = fd;
  if (epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, fd, &ev) != 0 && errno == EEXIST)
    epoll_ctl(epoll_fd_, EPOLL_CTL_MOD, fd, &ev);
}

void EpollTimer::unwatch(int fd) {
  if (fd >= 0) epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, fd, nullptr);
}

std::uint64_t EpollTimer::wait() {
  epoll_event events[8];
  const int n = epoll_wait(epoll_fd_, events, 8, -1);
  std::uint64_t expirations = 0;
  for (int i = 0; i < n; ++i) {
    if (events[i].data.fd != timer_fd_) continue;
    std::uint64_t count = 0;
    if (read(timer_fd_, &count, sizeof count) == static_cast<ssize_t>(sizeof count))
      expirations += count;
  }
  return expirations;
}

}  // namespace planter::hal::linux_backend
