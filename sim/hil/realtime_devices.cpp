#include "sim/hil/realtime_devices.h"

#include <csignal>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "hal/linux/epoll_timer.h"
#include "hal/linux/monotonic_clock.h"
#include "hal/linux/socketcan_bus.h"
#include "sim/hil/can_bridge.h"
#include "sim/hil/gpio_sim_lines.h"
#include "sim/machine/realtime_driver.h"
#include "sim/machine/simulated_machine.h"
#include "sim/plant/truth_columns.h"

namespace planter::sim {
namespace {

// The board's lines on a gpio-sim chip: encoder and e-stop are driven by pull, the status lamp
// is read back from what the controller drives.
class GpioSimMachineLines final : public MachineLines {
 public:
  GpioSimMachineLines(GpioSimLines& gpio, bool estop_active_low, bool photo_eye,
                      bool photo_eye_active_low)
      : gpio_(gpio),
        estop_active_low_(estop_active_low),
        photo_eye_(photo_eye),
        photo_eye_active_low_(photo_eye_active_low) {
    gpio_.set(0, false);
    gpio_.set(1, false);
    if (photo_eye_) gpio_.set(4, photo_eye_active_low_);  // beam clear
  }
  // gpio-sim stamps the edge itself, when the pull changes.
  void line_edge(const hal::GpioEdge& e) override {
    if (e.line == hal::edge_line::kSeedlingSensor) {
      if (photo_eye_) gpio_.set(4, photo_eye_active_low_ ? !e.rising : e.rising);
      return;
    }
    gpio_.set(e.line == hal::edge_line::kEncoderA ? 0 : 1, e.rising);
  }
  void set_estop(bool asserted) override { gpio_.set(2, estop_active_low_ ? !asserted : asserted); }
  bool lamp() override { return gpio_.output_level(3); }

 private:
  GpioSimLines& gpio_;
  bool estop_active_low_;
  bool photo_eye_;
  bool photo_eye_active_low_;
};

double wall_s() { return static_cast<double>(hal::linux_backend::realtime_now_ns()) * 1e-9; }

}  // namespace

RealtimeDevicesResult run_realtime_devices(const Scenario& scenario,
                                           const RealtimeDevicesOptions& options,
                                           const std::atomic<bool>& stop) {
  using hal::linux_backend::monotonic_now_ns;
  const config::GpioLines& lines = scenario.board.gpio;
  hal::linux_backend::SocketCanBus socket(options.can_interface);
  std::vector<int> offsets{lines.encoder_a, lines.encoder_b, lines.estop, lines.status};
  if (lines.seedling_sensor >= 0) offsets.push_back(lines.seedling_sensor);
  GpioSimLines gpio(options.gpio_chip, offsets);
  std::fprintf(stderr, "planter-sim devices: nodes %d %d %d %d on %s, encoder on %s\n",
               scenario.board.controller.node(NodeRole::kDiscDrive).node_id,
               scenario.board.controller.node(NodeRole::kRollerActuator).node_id,
               scenario.board.controller.node(NodeRole::kDepthActuator).node_id,
               scenario.board.controller.node(NodeRole::kForceSensor).node_id,
               options.can_interface.c_str(), options.gpio_chip.c_str());
  hal::sim::VirtualCanBus bus(scenario.board.controller.can.bitrate_bps);
  SimulatedMachine machine(scenario, bus);
  CanBridge bridge(socket, bus);
  GpioSimMachineLines machine_lines(gpio, scenario.board.controller.estop_active_low,
                                    lines.seedling_sensor >= 0, lines.seedling_sensor_active_low);
  RealtimeDriver driver(scenario, machine, machine_lines);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> truth(nullptr, &std::fclose);
  if (!options.truth_path.empty()) {
    truth.reset(std::fopen(options.truth_path.c_str(), "w"));
    if (!truth) throw std::runtime_error(options.truth_path + ": cannot open for writing");
    std::fprintf(truth.get(),
                 "# source: planter-sim devices\n# scenario: %s\nt,wall_time,%s,moving,estop\n",
                 scenario.name.c_str(), truth_header().c_str());
  }
  std::uint64_t steps = 0;
  std::size_t events_shown = 0;
  driver.on_step = [&](std::int64_t sim_ns, const ScriptActions& a) {
    // The script's events, stamped with the wall clock at the step they happened in (the HIL
    // check lines them up with candump's timestamps).
    const auto& events = driver.script().timeline();
    for (; events_shown < events.size(); ++events_shown)
      std::fprintf(stderr, "planter-sim devices: %s at wall %.6f\n",
                   events[events_shown].what.c_str(), wall_s());
    if (!truth || ++steps % 10 != 0) return;
    const PlantTruth& p = machine.plant().truth();
    std::fprintf(truth.get(), "%.3f,%.6f", static_cast<double>(sim_ns) * 1e-9, wall_s());
    for (const TruthColumn& c : kTruthColumns)
      std::fprintf(truth.get(), ",%.*f", c.decimals, p.*c.value);
    std::fprintf(truth.get(), ",%d,%d\n", driver.script().moving() ? 1 : 0, a.estop ? 1 : 0);
  };

  hal::linux_backend::EpollTimer timer(RealtimeDriver::kStepNs);
  int watched_fd = socket.fd();
  timer.watch(watched_fd);
  const std::int64_t start_ns = monotonic_now_ns();
  bool presses_shown = false;
  RealtimeDevicesResult result;
  while (!stop) {
    const std::uint64_t expired = timer.wait();
    bridge.inbound();
    driver.process_devices();
    if (expired > 0) {
      // planterd runs in another process: its state is not seen here, only its lamp.
      const OperatorPresses presses = driver.catch_up(monotonic_now_ns() - start_ns, {});
      if ((presses.run || presses.stop) && !presses_shown) {
        std::fprintf(stderr,
                     "planter-sim devices: the scenario's operator pressed %s, which cannot reach "
                     "planterd (it takes no operator input but --run and signals): it keeps "
                     "planting\n",
                     presses.stop ? "stop at a planting-off stop" : "run");
        presses_shown = true;
      }
    }
    bridge.outbound();
    // The socket is reopened after the link went down: watch the new descriptor.
    if (socket.fd() != watched_fd) {
      timer.unwatch(watched_fd);
      watched_fd = socket.fd();
      timer.watch(watched_fd);
    }
    const double t = static_cast<double>(driver.sim_ns()) * 1e-9;
    const double finished_at_s = driver.finished_at_s();
    if (options.duration_s > 0.0 ? t >= options.duration_s
                                 : finished_at_s >= 0.0 && t >= finished_at_s + scenario.tail_s)
      break;
  }
  result.late_steps = driver.late_steps();
  result.seconds = static_cast<double>(driver.sim_ns()) * 1e-9;
  result.distance_m = machine.plant().ground().x_m();
  for (const Seedling& s : machine.plant().seedlings().seedlings())
    result.seedlings_planted += s.planted;
  result.frames_in = bridge.frames_in();
  result.frames_out = bridge.frames_out();
  result.frames_lost = bridge.frames_lost();
  result.gpio_writes = gpio.writes();
  result.link_downs = socket.link_down_count();
  result.reopens = socket.reopen_count();
  return result;
}

}  // namespace planter::sim
