#pragma once
// The simulated machine as the controller's bus sees it: the four CANopen devices, each on its
// own endpoint of a virtual bus, and the plant they act on. One machine for every driver: the
// lockstep runner puts the controller on the same virtual bus, `planter-sim devices` bridges it
// to a real SocketCAN bus, planter-can's `--iface sim` puts the tool on it. What happens to it
// (the operator, e-stops, silent nodes) is the ScenarioScript's (scenario_script.h).
#include <array>
#include <cstdint>
#include <memory>

#include "hal/sim/sim_gpio.h"
#include "hal/sim/virtual_can_bus.h"
#include "sim/devices/cia402_drive_device.h"
#include "sim/plant/plant.h"
#include "sim/runner/scenario.h"

namespace planter::sim {

class SimulatedMachine {
 public:
  // The board's GNSS receiver: the plant's receiver model delivers its fixes here.
  void fit_gnss(hal::sim::SimGnss& gnss) { devices_->gnss = &gnss; }
  SimulatedMachine(const Scenario& scenario, hal::sim::VirtualCanBus& bus);

  // Devices read their frames and answer (SDO, NMT, PDO on SYNC, heartbeats).
  void process_devices(std::int64_t now_ns);
  // Integrates the plant over one step; encoder edges go to `edges`.
  void step_plant(std::int64_t now_ns, std::int64_t dt_ns, hal::sim::SimEdgeSource& edges);
  // A node stops answering (the script's silent node).
  void silence(NodeRole role) { endpoint(role).set_unplugged(true); }

  Cia402DriveDevice& drive(NodeRole role);
  Cia404ForceSensor& force_sensor() { return *force_; }
  hal::sim::VirtualCanEndpoint& endpoint(NodeRole role) {
    return *endpoints_[static_cast<std::size_t>(role)];
  }
  Plant& plant() { return *plant_; }
  [[nodiscard]] const Plant& plant() const { return *plant_; }

 private:
  const Scenario& scenario_;
  std::array<hal::sim::VirtualCanEndpoint*, kNodeCount> endpoints_{};
  std::unique_ptr<Cia402DriveDevice> disc_, roller_, depth_;
  std::unique_ptr<Cia404ForceSensor> force_;
  std::unique_ptr<Plant> plant_;
  std::unique_ptr<PlantDevices> devices_;
};

}  // namespace planter::sim
