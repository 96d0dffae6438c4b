#include "apps/planterd/board_hardware.h"

#include "hal/linux/gpsd_receiver.h"
#include "hal/linux/hal_error.h"
#include "hal/linux/monotonic_clock.h"

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

std::unique_ptr<hal::GnssSource> gnss_of(const config::BoardConfig& board) {
  if (board.gnss.receiver == "sim")
    throw hal::linux_backend::HalError(
        "'gnss.receiver': board '" + board.name +
        "' names the simulator's receiver; on a board planterd reads a receiver through gpsd "
        "(receiver = \"gpsd\")");
  if (board.gnss.receiver != "gpsd") return nullptr;
#ifndef PLANTER_HAVE_GPSD
  throw hal::linux_backend::HalError(
      "'gnss.receiver': board '" + board.name +
      "' reads its receiver through gpsd, and this planterd was built without gpsd's library "
      "(libgps-dev); build it where libgps-dev is installed");
#else
  hal::linux_backend::GpsdOptions o;
  o.host = board.gnss.gpsd_host;
  o.port = board.gnss.gpsd_port;
  return std::make_unique<hal::linux_backend::GpsdReceiver>(
      o, [] { return hal::linux_backend::monotonic_now_ns(); });
#endif
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
      gnss_(gnss_of(board)),
      hal_{can_, probe_, estop_, status_} {
  hal_.gnss = gnss_.get();
}

}  // namespace planter::daemon
