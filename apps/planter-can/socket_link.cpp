#include "apps/planter-can/socket_link.h"

#include <sys/epoll.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>

#include "hal/linux/gpiod_lines.h"
#include "hal/linux/hal_error.h"
#include "hal/linux/monotonic_clock.h"

namespace planter::cantool {

SocketLink::SocketLink(const std::string& interface) : bus_(interface) {
  epoll_fd_ = epoll_create1(EPOLL_CLOEXEC);
  if (epoll_fd_ < 0) throw hal::linux_backend::HalError("epoll_create1 failed");
}

SocketLink::~SocketLink() {
  if (epoll_fd_ >= 0) close(epoll_fd_);
}

std::int64_t SocketLink::now_ns() { return hal::linux_backend::monotonic_now_ns(); }
std::int64_t SocketLink::wall_time_ns() { return hal::linux_backend::realtime_now_ns(); }
std::int64_t SocketLink::rx_time_ns() {
  const std::int64_t t = bus_.last_rx_time_ns();
  return t > 0 ? t : wall_time_ns();
}

void SocketLink::open_encoder(const config::BoardConfig& board) {
  chip_ = std::make_unique<hal::linux_backend::GpiodChip>(board.gpio.chip);
  encoder_ = std::make_unique<hal::linux_backend::GpiodEdgeSource>(*chip_, board.gpio.encoder_a,
                                                                   board.gpio.encoder_b);
}

hal::GpioEdgeSource* SocketLink::encoder() { return encoder_.get(); }

void SocketLink::back_off() {
  const timespec ts{0, 1'000'000};
  nanosleep(&ts, nullptr);
}

bool SocketLink::wait(std::int64_t deadline_ns) {
  for (;;) {
    // The socket may have been reopened after a link loss: watch the current descriptor.
    if (bus_.fd() != watched_fd_) {
      if (watched_fd_ >= 0) epoll_ctl(epoll_fd_, EPOLL_CTL_DEL, watched_fd_, nullptr);
      watched_fd_ = bus_.fd();
      if (watched_fd_ >= 0) {
        epoll_event ev{};
        ev.events = EPOLLIN;
        ev.data.fd = watched_fd_;
        epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, watched_fd_, &ev);
      }
    }
    const std::int64_t left_ns = deadline_ns - now_ns();
    if (left_ns <= 0) return false;
    // A down link is polled every 50 ms so the reopen happens.
    int timeout_ms = static_cast<int>((left_ns + 999'999) / 1'000'000);
    if (watched_fd_ < 0 && timeout_ms > 50) timeout_ms = 50;
    epoll_event ev{};
    const int n = epoll_wait(epoll_fd_, &ev, 1, timeout_ms);
    if (n > 0) return true;
    if (n < 0 && errno != EINTR) return false;
    if (watched_fd_ < 0) return true;  // let the caller's receive() try the reopen
  }
}

}  // namespace planter::cantool
