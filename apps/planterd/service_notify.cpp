#include "apps/planterd/service_notify.h"

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace planter::daemon {

ServiceNotifier::ServiceNotifier() {
  const char* socket_name = std::getenv("NOTIFY_SOCKET");
  if (socket_name != nullptr && (socket_name[0] == '/' || socket_name[0] == '@') &&
      std::strlen(socket_name) < sizeof(sockaddr_un::sun_path)) {
    address_ = socket_name;
    if (address_[0] == '@') address_[0] = '\0';  // abstract namespace
    fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  }
  const char* usec = std::getenv("WATCHDOG_USEC");
  const char* pid = std::getenv("WATCHDOG_PID");
  if (usec != nullptr) {
    char* end = nullptr;
    const unsigned long long v = std::strtoull(usec, &end, 10);
    // WATCHDOG_PID, when set, must name this process (not a parent that exec'd us).
    const bool ours = pid == nullptr || std::strtol(pid, nullptr, 10) == ::getpid();
    if (end != usec && *end == '\0' && v > 0 && ours) watchdog_us_ = v;
  }
}

ServiceNotifier::~ServiceNotifier() {
  if (fd_ >= 0) ::close(fd_);
}

bool ServiceNotifier::notify(const std::string& state) {
  if (fd_ < 0) return false;
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::memcpy(addr.sun_path, address_.data(), address_.size());
  const auto len = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + address_.size() +
                                          (address_[0] == '\0' ? 0 : 1));
  const ssize_t n = ::sendto(fd_, state.data(), state.size(), MSG_NOSIGNAL,
                             reinterpret_cast<const sockaddr*>(&addr), len);
  return n == static_cast<ssize_t>(state.size());
}

bool ServiceNotifier::watchdog_enabled(std::uint64_t& period_us) const {
  period_us = watchdog_us_;
  return watchdog_us_ > 0;
}

}  // namespace planter::daemon
