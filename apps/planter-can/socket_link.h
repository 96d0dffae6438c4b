#pragma once
// A real SocketCAN interface (can0, vcan0) and, when the board names a GPIO chip, the
// soil-wheel encoder lines through libgpiod. Waits in epoll on the socket.
#include <memory>
#include <string>

#include "apps/planter-can/tool_link.h"
#include "config/board_config.h"
#include "hal/linux/socketcan_bus.h"

namespace planter::hal::linux_backend {
class GpiodChip;
class GpiodEdgeSource;
}  // namespace planter::hal::linux_backend

namespace planter::cantool {

class SocketLink final : public ToolLink {
 public:
  // Throws hal::linux_backend::HalError when the interface cannot be opened.
  explicit SocketLink(const std::string& interface);
  ~SocketLink() override;

  bool wait(std::int64_t deadline_ns) override;
  std::int64_t now_ns() override;
  std::int64_t wall_time_ns() override;
  std::int64_t rx_time_ns() override;
  hal::GpioEdgeSource* encoder() override;
  [[nodiscard]] std::string name() const override { return bus_.interface(); }
  [[nodiscard]] hal::CanBusCounters counters() const override { return bus_.counters(); }

  // Opens the board's encoder lines; throws HalError naming the board key on failure.
  void open_encoder(const config::BoardConfig& board);

 protected:
  bool try_send(const hal::CanFrame& frame) override { return bus_.send(frame); }
  bool try_receive(hal::CanFrame& frame) override { return bus_.receive(frame); }
  void back_off() override;

 private:
  hal::linux_backend::SocketCanBus bus_;
  int epoll_fd_ = -1;
  int watched_fd_ = -1;
  std::unique_ptr<hal::linux_backend::GpiodChip> chip_;
  std::unique_ptr<hal::linux_backend::GpiodEdgeSource> encoder_;
};

}  // namespace planter::cantool
