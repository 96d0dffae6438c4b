#pragma once
// Talks to the service manager the way sd_notify(3) describes (a datagram of "KEY=value"
// lines to the AF_UNIX socket named in $NOTIFY_SOCKET; the watchdog period in $WATCHDOG_USEC
// for the process in $WATCHDOG_PID). The protocol is small and stable, and doing it here keeps
// libsystemd and its compression and crypto libraries off the controller image.
#include <cstdint>
#include <string>

namespace planter::daemon {

class ServiceNotifier {
 public:
  // Reads the environment once (as systemd sets it before exec).
  ServiceNotifier();
  ~ServiceNotifier();
  ServiceNotifier(const ServiceNotifier&) = delete;
  ServiceNotifier& operator=(const ServiceNotifier&) = delete;

  // Sends one state message ("READY=1", "WATCHDOG=1", "STATUS=..."); false when there is no
  // service manager to tell or the send failed. Never blocks.
  bool notify(const std::string& state);
  // The watchdog period the manager expects pings within, when it watches this process.
  [[nodiscard]] bool watchdog_enabled(std::uint64_t& period_us) const;
  [[nodiscard]] bool active() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
  std::string address_;  // sun_path bytes; a leading '\0' for the abstract namespace
  std::uint64_t watchdog_us_ = 0;
};

}  // namespace planter::daemon
