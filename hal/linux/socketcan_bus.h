#pragma once
// CanBus over a SocketCAN raw socket: non-blocking, standard data frames only (EFF and RTR
// filtered out in the kernel), error frames counted, receive-queue drops counted
// (SO_RXQ_OVFL), kernel timestamps, and a reopen after the interface disappears or goes down.
#include <cstdint>
#include <string>

#include "planter/hal/can_bus.h"

namespace planter::hal::linux_backend {

struct SocketCanOptions {
  bool receive_own = false;        // a recorder wants its own frames too
  std::uint32_t restart_ms = 100;  // bus-off auto-restart written through libsocketcan
  std::int64_t reopen_interval_ns = 50'000'000;
};

class SocketCanBus final : public CanBus {
 public:
  // Throws HalError when the interface does not exist or the socket cannot be opened.
  explicit SocketCanBus(std::string interface, SocketCanOptions options = {});
  ~SocketCanBus() override;
  SocketCanBus(const SocketCanBus&) = delete;
  SocketCanBus& operator=(const SocketCanBus&) = delete;

  bool send(const CanFrame& frame) override;
  bool receive(CanFrame& frame) override;
  [[nodiscard]] CanBusCounters counters() const override {
    CanBusCounters c = counters_;
    c.link_up = link_up();
    c.link_downs = link_downs_;
    return c;
  }

  // Kernel timestamp of the last frame receive() returned (hardware when the adapter gives
  // one, else software), CLOCK_REALTIME ns for software stamps (what candump prints).
  [[nodiscard]] std::int64_t last_rx_time_ns() const { return last_rx_ns_; }
  [[nodiscard]] bool last_rx_time_is_hardware() const { return last_rx_hw_; }
  // -1 while the link is down and not yet reopened.
  [[nodiscard]] int fd() const { return fd_; }
  [[nodiscard]] bool link_up() const { return fd_ >= 0; }
  [[nodiscard]] std::uint32_t reopen_count() const { return reopens_; }
  [[nodiscard]] std::uint32_t link_down_count() const { return link_downs_; }
  [[nodiscard]] const std::string& interface() const { return interface_; }
  // True when the kernel's bus-off auto-restart was set (real CAN controllers only).
  [[nodiscard]] bool restart_configured() const { return restart_configured_; }

 private:
  bool open_socket();
  void close_socket();
  void link_lost();
  bool try_reopen();
  void on_error_frame(std::uint32_t can_id, const std::uint8_t* data);

  std::string interface_;
  SocketCanOptions options_;
  int fd_ = -1;
  CanBusCounters counters_{};
  std::uint32_t kernel_drops_seen_ = 0;
  std::int64_t last_rx_ns_ = 0;
  bool last_rx_hw_ = false;
  std::int64_t next_reopen_ns_ = 0;
  std::uint32_t reopens_ = 0;
  std::uint32_t link_downs_ = 0;
  bool restart_configured_ = false;
};

}  // namespace planter::hal::linux_backend
