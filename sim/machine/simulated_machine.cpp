#include "sim/machine/simulated_machine.h"

namespace planter::sim {
namespace {

DeviceIdentity identity_of(const NodeConfig& n, const char* name) {
  DeviceIdentity id;
  id.node_id = n.node_id;
  id.device_type = n.profile;
  id.vendor_id = n.vendor_id;
  id.product_code = n.product_code;
  id.name = name;
  return id;
}

}  // namespace

SimulatedMachine::SimulatedMachine(const Scenario& scenario, hal::sim::VirtualCanBus& bus)
    : scenario_(scenario) {
  const ControllerConfig& cfg = scenario_.board.controller;
  for (auto& e : endpoints_) e = &bus.add_endpoint(256);
  disc_ = std::make_unique<Cia402DriveDevice>(
      identity_of(cfg.node(NodeRole::kDiscDrive), "sim disc drive"), *endpoints_[0]);
  roller_ = std::make_unique<Cia402DriveDevice>(
      identity_of(cfg.node(NodeRole::kRollerActuator), "sim roller actuator"), *endpoints_[1]);
  depth_ = std::make_unique<Cia402DriveDevice>(
      identity_of(cfg.node(NodeRole::kDepthActuator), "sim depth actuator"), *endpoints_[2]);
  force_ = std::make_unique<Cia404ForceSensor>(
      identity_of(cfg.node(NodeRole::kForceSensor), "sim load cell"), *endpoints_[3]);
  plant_ = std::make_unique<Plant>(scenario_.plant, cfg, scenario_.seed);
  devices_ = std::make_unique<PlantDevices>(PlantDevices{*disc_, *roller_, *depth_, *force_});
  disc_->power_on(0);
  roller_->power_on(0);
  depth_->power_on(0);
  force_->power_on(0);
}

Cia402DriveDevice& SimulatedMachine::drive(NodeRole role) {
  switch (role) {
    case NodeRole::kRollerActuator:
      return *roller_;
    case NodeRole::kDepthActuator:
      return *depth_;
    default:
      return *disc_;
  }
}

void SimulatedMachine::process_devices(std::int64_t now_ns) {
  disc_->process(now_ns);
  roller_->process(now_ns);
  depth_->process(now_ns);
  force_->process(now_ns);
}

void SimulatedMachine::step_plant(std::int64_t now_ns, std::int64_t dt_ns,
                                  hal::sim::SimEdgeSource& edges) {
  plant_->step(now_ns, dt_ns, *devices_, edges);
}

}  // namespace planter::sim
