// planterd's messages to the service manager, against a socket playing systemd.
#include "apps/planterd/service_notify.h"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>

namespace {

class FakeManager {
 public:
  explicit FakeManager(const std::string& name) {
    fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::string path = name;
    if (path[0] == '@') path[0] = '\0';
    std::memcpy(addr.sun_path, path.data(), path.size());
    const auto len = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + path.size() +
                                            (path[0] == '\0' ? 0 : 1));
    EXPECT_EQ(::bind(fd_, reinterpret_cast<sockaddr*>(&addr), len), 0);
  }
  ~FakeManager() { ::close(fd_); }
  std::string receive() {
    char buf[256];
    const ssize_t n = ::recv(fd_, buf, sizeof buf, MSG_DONTWAIT);
    return n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : "";
  }

 private:
  int fd_;
};

TEST(ServiceNotifier, SendsStatesToThePathSocket) {
  const std::string path = "/tmp/planter-notify-" + std::to_string(::getpid());
  ::unlink(path.c_str());
  FakeManager manager(path);
  ::setenv("NOTIFY_SOCKET", path.c_str(), 1);
  planter::daemon::ServiceNotifier n;
  EXPECT_TRUE(n.notify("READY=1\nSTATUS=booting"));
  EXPECT_EQ(manager.receive(), "READY=1\nSTATUS=booting");
  EXPECT_TRUE(n.notify("WATCHDOG=1"));
  EXPECT_EQ(manager.receive(), "WATCHDOG=1");
  ::unlink(path.c_str());
  ::unsetenv("NOTIFY_SOCKET");
}

TEST(ServiceNotifier, SendsToAnAbstractSocket) {
  const std::string name = "@planter-notify-" + std::to_string(::getpid());
  FakeManager manager(name);
  ::setenv("NOTIFY_SOCKET", name.c_str(), 1);
  planter::daemon::ServiceNotifier n;
  EXPECT_TRUE(n.notify("STOPPING=1"));
  EXPECT_EQ(manager.receive(), "STOPPING=1");
  ::unsetenv("NOTIFY_SOCKET");
}

TEST(ServiceNotifier, QuietWithoutAManagerAndWatchdogOnlyForThisProcess) {
  ::unsetenv("NOTIFY_SOCKET");
  ::setenv("WATCHDOG_USEC", "2000000", 1);
  ::setenv("WATCHDOG_PID", std::to_string(::getpid()).c_str(), 1);
  {
    planter::daemon::ServiceNotifier n;
    EXPECT_FALSE(n.active());
    EXPECT_FALSE(n.notify("READY=1"));
    std::uint64_t us = 0;
    EXPECT_TRUE(n.watchdog_enabled(us));
    EXPECT_EQ(us, 2'000'000u);
  }
  ::setenv("WATCHDOG_PID", "1", 1);  // meant for another process
  {
    planter::daemon::ServiceNotifier n;
    std::uint64_t us = 0;
    EXPECT_FALSE(n.watchdog_enabled(us));
  }
  ::setenv("WATCHDOG_PID", std::to_string(::getpid()).c_str(), 1);
  ::setenv("WATCHDOG_USEC", "soon", 1);
  {
    planter::daemon::ServiceNotifier n;
    std::uint64_t us = 0;
    EXPECT_FALSE(n.watchdog_enabled(us));
  }
  ::unsetenv("WATCHDOG_USEC");
  ::unsetenv("WATCHDOG_PID");
}

}  // namespace
