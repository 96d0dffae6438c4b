#pragma once
// The simulated machine in real time: on every wake-up the devices answer what arrived, and the
// machine catches up with wall time in fixed 1 ms steps (the script, the devices, the plant,
// the encoder lines), so the physics never sees a long step however late the wake-up. Where the
// bus and the lines go is the caller's: `planter-sim devices` bridges the bus to SocketCAN and
// the lines to gpio-sim; a test keeps both in process with a controller beside them.
#include <cstdint>
#include <functional>

#include "sim/machine/scenario_script.h"
#include "sim/machine/simulated_machine.h"

namespace planter::sim {

// The machine's GPIO lines as the controller's board sees them.
class MachineLines {
 public:
  virtual ~MachineLines() = default;
  // An edge of an input line (hal::edge_line::: encoder A, B, the seedling photo-eye), with
  // the plant's time of it.
  virtual void line_edge(const hal::GpioEdge& edge) = 0;
  virtual void set_estop(bool asserted) = 0;
  [[nodiscard]] virtual bool lamp() = 0;  // the controller's status lamp: on while planting
};

// The operator's presses during one catch-up, for a driver that can deliver them.
struct OperatorPresses {
  bool run = false;
  bool stop = false;
};

class RealtimeDriver {
 public:
  static constexpr std::int64_t kStepNs = 1'000'000;

  RealtimeDriver(const Scenario& scenario, SimulatedMachine& machine, MachineLines& lines);

  // The devices answer the frames that arrived (every wake-up).
  void process_devices() { machine_.process_devices(sim_ns_); }
  // Catches up to `wall_ns` (time since start). `controller` is what the caller knows of the
  // controller besides its lamp (state_known false for a controller in another process).
  OperatorPresses catch_up(std::int64_t wall_ns, const ControllerView& controller);

  // Called after every step (ground truth files).
  std::function<void(std::int64_t sim_ns, const ScriptActions& actions)> on_step;

  [[nodiscard]] std::int64_t sim_ns() const { return sim_ns_; }
  [[nodiscard]] const ScenarioScript& script() const { return script_; }
  // Scenario time when the route was finished (-1: not yet).
  [[nodiscard]] double finished_at_s() const { return finished_at_s_; }
  [[nodiscard]] std::uint64_t late_steps() const { return late_steps_; }

 private:
  SimulatedMachine& machine_;
  MachineLines& lines_;
  ScenarioScript script_;
  hal::sim::SimEdgeSource edges_;
  std::int64_t sim_ns_ = 0;
  double finished_at_s_ = -1.0;
  std::uint64_t late_steps_ = 0;
  bool estop_driven_;
};

}  // namespace planter::sim
