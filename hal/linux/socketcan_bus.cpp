#include "hal/linux/socketcan_bus.h"

#include <errno.h>
#include <fcntl.h>
#include <libsocketcan.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <linux/errqueue.h>
#include <linux/net_tstamp.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <climits>
#include <cstring>

#include "hal/linux/hal_error.h"
#include "hal/linux/monotonic_clock.h"

namespace planter::hal::linux_backend {
namespace {

bool interface_up(const std::string& name) {
  const int s = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (s < 0) return false;
  ifreq ifr{};
  std::strncpy(ifr.ifr_name, name.c_str(), IFNAMSIZ - 1);
  const bool up = ioctl(s, SIOCGIFFLAGS, &ifr) == 0 && (ifr.ifr_flags & IFF_UP) != 0;
  close(s);
  return up;
}

bool is_virtual(const std::string& name) {
  char target[PATH_MAX];
  const std::string link = "/sys/class/net/" + name;
  const ssize_t n = readlink(link.c_str(), target, sizeof target - 1);
  if (n <= 0) return false;
  target[n] = 0;
  return std::strstr(target, "/virtual/") != nullptr;
}

bool link_gone(int err) { return err == ENETDOWN || err == ENODEV || err == ENXIO; }

}  // namespace

SocketCanBus::SocketCanBus(std::string interface, SocketCanOptions options)
    : interface_(std::move(interface)), options_(options) {
  if (interface_.empty() || interface_.size() >= IFNAMSIZ)
    throw HalError("can: interface name '" + interface_ + "' is not a valid name (1-15 chars)");
  if (if_nametoindex(interface_.c_str()) == 0)
    throw HalError("'can.interface': '" + interface_ +
                   "' does not exist (`ip link` lists the interfaces)");
  // Bus-off recovery by the kernel itself (restart-ms). Virtual interfaces (vcan) have none.
  if (options_.restart_ms > 0 && !is_virtual(interface_))
    restart_configured_ = can_set_restart_ms(interface_.c_str(), options_.restart_ms) == 0;
  if (!open_socket()) {
    const int err = errno;
    throw HalError("can: cannot open a raw CAN socket on '" + interface_ +
                   "': " + std::strerror(err) +
                   (err == EAFNOSUPPORT ? " (this kernel has no CAN support)" : ""));
  }
  if (!interface_up(interface_)) link_lost();
}

SocketCanBus::~SocketCanBus() { close_socket(); }

bool SocketCanBus::open_socket() {
  const int fd = socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) return false;
  // Standard data frames only: the mask includes EFF and RTR so they must be 0.
  can_filter filter{};
  filter.can_id = 0;
  filter.can_mask = CAN_EFF_FLAG | CAN_RTR_FLAG;
  can_err_mask_t err_mask = CAN_ERR_MASK;
  const int one = 1;
  const int own = options_.receive_own ? 1 : 0;
  const int stamping = SOF_TIMESTAMPING_RX_SOFTWARE | SOF_TIMESTAMPING_SOFTWARE |
                       SOF_TIMESTAMPING_RX_HARDWARE | SOF_TIMESTAMPING_RAW_HARDWARE;
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = static_cast<int>(if_nametoindex(interface_.c_str()));
  if (addr.can_ifindex == 0 ||
      setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, &filter, sizeof filter) != 0 ||
      setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &err_mask, sizeof err_mask) != 0 ||
      setsockopt(fd, SOL_CAN_RAW, CAN_RAW_RECV_OWN_MSGS, &own, sizeof own) != 0 ||
      setsockopt(fd, SOL_SOCKET, SO_RXQ_OVFL, &one, sizeof one) != 0 ||
      setsockopt(fd, SOL_SOCKET, SO_TIMESTAMPING, &stamping, sizeof stamping) != 0 ||
      bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    const int err = errno;
    close(fd);
    errno = err;
    return false;
  }
  fd_ = fd;
  kernel_drops_seen_ = 0;
  return true;
}

void SocketCanBus::close_socket() {
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
}

void SocketCanBus::link_lost() {
  close_socket();
  ++link_downs_;
  next_reopen_ns_ = monotonic_now_ns() + options_.reopen_interval_ns;
}

bool SocketCanBus::try_reopen() {
  const std::int64_t now = monotonic_now_ns();
  if (now < next_reopen_ns_) return false;
  next_reopen_ns_ = now + options_.reopen_interval_ns;
  if (!interface_up(interface_) || !open_socket()) return false;
  ++reopens_;
  counters_.bus_off = false;
  return true;
}

void SocketCanBus::on_error_frame(std::uint32_t can_id, const std::uint8_t* data) {
  ++counters_.error_frames;
  if ((can_id & CAN_ERR_BUSOFF) != 0) counters_.bus_off = true;
  if ((can_id & CAN_ERR_RESTARTED) != 0) counters_.bus_off = false;
  if ((can_id & CAN_ERR_CRTL) != 0 && (data[1] & CAN_ERR_CRTL_ACTIVE) != 0)
    counters_.bus_off = false;
}

bool SocketCanBus::send(const CanFrame& frame) {
  if (fd_ < 0 && !try_reopen()) {
    ++counters_.tx_dropped;
    return false;
  }
  can_frame cf{};
  cf.can_id = frame.id & (CAN_EFF_FLAG | CAN_RTR_FLAG | CAN_EFF_MASK);
  cf.len = frame.dlc > 8 ? 8 : frame.dlc;
  std::memcpy(cf.data, frame.data.data(), cf.len);
  const ssize_t n = write(fd_, &cf, sizeof cf);
  if (n == static_cast<ssize_t>(sizeof cf)) {
    ++counters_.tx_frames;
    return true;
  }
  // EAGAIN/ENOBUFS: the tx queue is full. Never retry here: the loop must not block.
  if (n < 0 && link_gone(errno)) link_lost();
  ++counters_.tx_dropped;
  return false;
}

bool SocketCanBus::receive(CanFrame& frame) {
  if (fd_ < 0 && !try_reopen()) return false;
  for (;;) {
    can_frame cf{};
    iovec iov{&cf, sizeof cf};
    alignas(cmsghdr) char
        control[CMSG_SPACE(sizeof(scm_timestamping)) + CMSG_SPACE(sizeof(std::uint32_t)) + 64];
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof control;
    std::int64_t software_stamp_ns = -1;
    const ssize_t n = recvmsg(fd_, &msg, MSG_DONTWAIT);
    if (n < 0) {
      if (errno == EINTR) continue;
      if (link_gone(errno)) link_lost();
      return false;  // EAGAIN: nothing pending
    }
    if (n != static_cast<ssize_t>(sizeof cf)) continue;  // not a classic CAN frame
    for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c != nullptr; c = CMSG_NXTHDR(&msg, c)) {
      if (c->cmsg_level != SOL_SOCKET) continue;
      if (c->cmsg_type == SO_RXQ_OVFL) {
        std::uint32_t drops = 0;
        std::memcpy(&drops, CMSG_DATA(c), sizeof drops);
        if (drops > kernel_drops_seen_) counters_.rx_overflow += drops - kernel_drops_seen_;
        kernel_drops_seen_ = drops;
      } else if (c->cmsg_type == SO_TIMESTAMPING) {
        scm_timestamping ts{};
        std::memcpy(&ts, CMSG_DATA(c), sizeof ts);
        last_rx_hw_ = ts.ts[2].tv_sec != 0 || ts.ts[2].tv_nsec != 0;
        const timespec& t = last_rx_hw_ ? ts.ts[2] : ts.ts[0];
        last_rx_ns_ = timespec_ns(t);
        if (ts.ts[0].tv_sec != 0 || ts.ts[0].tv_nsec != 0)
          software_stamp_ns = timespec_ns(ts.ts[0]);
      }
    }
    if ((cf.can_id & CAN_ERR_FLAG) != 0) {
      on_error_frame(cf.can_id, cf.data);
      continue;
    }
    if ((cf.can_id & (CAN_EFF_FLAG | CAN_RTR_FLAG)) != 0) continue;
    frame.id = cf.can_id & CAN_SFF_MASK;
    frame.dlc = cf.len > 8 ? 8 : cf.len;
    frame.data = {};
    std::memcpy(frame.data.data(), cf.data, frame.dlc);
    // The kernel stamps on CLOCK_REALTIME; the controller's clock is CLOCK_MONOTONIC: the
    // frame's age, taken now, carries the stamp across.
    frame.rx_time_ns = -1;
    if (software_stamp_ns >= 0) {
      const std::int64_t age = realtime_now_ns() - software_stamp_ns;
      frame.rx_time_ns = monotonic_now_ns() - (age > 0 ? age : 0);
    }
    ++counters_.rx_frames;
    return true;
  }
}

}  // namespace planter::hal::linux_backend
