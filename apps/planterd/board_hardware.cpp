#include "apps/planterd/board_hardware.h"

#include "hal/linux/hal_error.h"

namespace planter::daemon {
namespace {

const std::string& checked_interface(const config::BoardConfig& board) {
  if (board.can_interface == "sim")
    throw hal::linux_backend::HalError(
        "'can.interface': board '" + board.name +
        "' uses the in-process sim bus; planterd needs a SocketCAN interface "
        "(run this board with `planter-sim run`)");
  return board.can_interface;
}

}  // namespace

BoardHardware::BoardHardware(const config::BoardConfig& board)
    : can_(checked_interface(board)),
      chip_(board.gpio.chip),
      edges_(chip_, board.gpio.encoder_a, board.gpio.encoder_b, board.gpio.seedling_sensor,
             board.gpio.seedling_sensor_active_low),
      estop_(chip_, board.gpio.estop, board.controller.estop_active_low, "gpio.estop_line"),
      status_(chip_, board.gpio.status, "gpio.status_line"),
      probe_(edges_),
      hal_{can_, probe_, estop_, status_} {}

}  // namespace planter::daemon
