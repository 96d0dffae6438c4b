#pragma once
// Every signal of the machine, declared once: its recording column (docs/recording-format.md), its
// unit, where it comes from, and for a bus signal the node, the object and the scale. The I/O
// layer's scaling, the recording header and row, planter-can's decode and monitor, the
// simulated devices' unit conversion and planter-fit's column units all derive from this table.
#include <array>
#include <cstdint>
#include <string_view>

#include "firmware/canopen/cia402.h"
#include "firmware/io/io_config.h"
#include "firmware/io/process_image.h"
#include "firmware/sensing/planting_monitor.h"

namespace planter {

// How a node's raw object value becomes SI (CiA 402 section 6 and CiA 404 conventions, with
// the board's per-node factors).
enum class BusScale : std::uint8_t {
  kNone,           // not on the bus
  kPerCount,       // raw / counts_per_unit: positions and velocities (0x6064, 0x606C, 0x607A...)
  kPerMilleRated,  // raw * 1e-3 * rated_torque: 0x6077, per mille of the rated torque or force
  kTared,          // (raw - zero_counts) / counts_per_unit: a load cell with its tare
};
double bus_to_si(BusScale scale, const NodeConfig& node, double raw);
double si_to_bus(BusScale scale, const NodeConfig& node, double si);

enum class SignalSource : std::uint8_t {
  kClock,       // the tick's time
  kEncoder,     // the soil-wheel encoder on the board's GPIO lines
  kNode,        // a node measures it and sends it in a TPDO
  kController,  // the controller decides it; a bus signal goes out in an RPDO
  kSupervisor,  // the supervisor's state name
  kWarnings,    // the supervisor's warning:: bits, as a number
  kMonitor,     // the planting monitor, from the seedling photo-eye
  kGnss,        // the GNSS receiver, where the board has one (hal/gnss.h)
};

struct SignalDecl {
  std::string_view column;   // recording column; also the name every tool shows
  std::string_view unit;     // SI, or mm where the column says so
  std::string_view meaning;  // the recording format's words
  SignalSource source;
  int decimals;   // printed precision in a recording row
  bool recorded;  // a column of the recording (false: in the process image only)
  // Where it lives in the process image (one of the two, or neither for t, counts, state).
  double MachineState::*measured = nullptr;
  double MachineCommand::*commanded = nullptr;
  double PlantingFigures::*monitored = nullptr;
  // The bus object (source kNode, or kController with an RPDO).
  NodeRole role = NodeRole::kDiscDrive;
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  BusScale scale = BusScale::kNone;

  [[nodiscard]] constexpr bool on_bus() const { return scale != BusScale::kNone; }
};

namespace signal_decl {
namespace c402 = canopen::cia402;
using MS = MachineState;
using MC = MachineCommand;
constexpr SignalDecl at(std::string_view column, std::string_view unit, std::string_view meaning,
                        SignalSource source, int decimals) {
  return SignalDecl{column, unit, meaning, source, decimals, true};
}
constexpr SignalDecl measured(std::string_view column, std::string_view unit,
                              std::string_view meaning, int decimals, double MS::*field,
                              NodeRole role = NodeRole::kDiscDrive, std::uint16_t index = 0,
                              std::uint8_t sub = 0, BusScale scale = BusScale::kNone) {
  return SignalDecl{
      column,   unit, meaning, index == 0 ? SignalSource::kEncoder : SignalSource::kNode,
      decimals, true, field,   nullptr,
      nullptr,  role, index,   sub,
      scale};
}
constexpr SignalDecl commanded(std::string_view column, std::string_view unit,
                               std::string_view meaning, int decimals, double MC::*field,
                               NodeRole role = NodeRole::kDiscDrive, std::uint16_t index = 0,
                               BusScale scale = BusScale::kNone, bool recorded = true) {
  return SignalDecl{column,   unit,     meaning, SignalSource::kController,
                    decimals, recorded, nullptr, field,
                    nullptr,  role,     index,   0,
                    scale};
}
constexpr SignalDecl gnss(std::string_view column, std::string_view unit, std::string_view meaning,
                          int decimals, double MS::*field) {
  return SignalDecl{column, unit, meaning, SignalSource::kGnss, decimals, true, field};
}
constexpr SignalDecl monitored(std::string_view column, std::string_view unit,
                               std::string_view meaning, int decimals,
                               double PlantingFigures::*field) {
  return SignalDecl{column,  unit,    meaning, SignalSource::kMonitor, decimals, true,
                    nullptr, nullptr, field};
}
}  // namespace signal_decl

// In recording order. A new signal is one line here (and its field in process_image.h).
inline constexpr std::array kSignals = {
    signal_decl::at("t", "s", "time", SignalSource::kClock, 3),
    signal_decl::at("wheel_counts", "counts", "cumulative soil-wheel encoder count",
                    SignalSource::kEncoder, 0),
    signal_decl::measured("v_wheel", "m/s", "ground speed from the encoder", 5,
                          &MachineState::v_wheel_mps),
    signal_decl::commanded("omega_cmd", "rad/s", "disc speed command", 5,
                           &MachineCommand::omega_cmd_radps, NodeRole::kDiscDrive,
                           signal_decl::c402::kTargetVelocity, BusScale::kPerCount),
    signal_decl::measured("omega", "rad/s", "measured disc speed", 5, &MachineState::omega_radps,
                          NodeRole::kDiscDrive, signal_decl::c402::kVelocityActual, 0,
                          BusScale::kPerCount),
    signal_decl::measured("disc_angle", "rad", "disc angle", 5, &MachineState::disc_angle_rad,
                          NodeRole::kDiscDrive, signal_decl::c402::kPositionActual, 0,
                          BusScale::kPerCount),
    signal_decl::measured("disc_torque", "N*m", "disc drive torque (from motor current)", 4,
                          &MachineState::disc_torque_Nm, NodeRole::kDiscDrive,
                          signal_decl::c402::kTorqueActual, 0, BusScale::kPerMilleRated),
    signal_decl::commanded("sigma", "1", "R*omega / v as the controller sees it", 4,
                           &MachineCommand::sigma),
    signal_decl::commanded("clamp_force_cmd", "N", "clamping force set-point", 2,
                           &MachineCommand::clamp_force_cmd_N),
    signal_decl::measured("clamp_pos_mm", "mm", "roller actuator position", 4,
                          &MachineState::clamp_pos_mm, NodeRole::kRollerActuator,
                          signal_decl::c402::kPositionActual, 0, BusScale::kPerCount),
    signal_decl::measured("clamp_force", "N", "measured clamping force", 2,
                          &MachineState::clamp_force_N, NodeRole::kForceSensor, 0x7130, 1,
                          BusScale::kTared),
    signal_decl::commanded("depth_cmd_mm", "mm", "furrow depth command", 3,
                           &MachineCommand::depth_cmd_mm, NodeRole::kDepthActuator,
                           signal_decl::c402::kTargetPosition, BusScale::kPerCount),
    signal_decl::measured("depth_mm", "mm", "measured furrow depth", 3, &MachineState::depth_mm,
                          NodeRole::kDepthActuator, signal_decl::c402::kPositionActual, 0,
                          BusScale::kPerCount),
    signal_decl::measured("depth_force", "N", "opener actuator force (soil draft on the opener)", 2,
                          &MachineState::depth_force_N, NodeRole::kDepthActuator,
                          signal_decl::c402::kTorqueActual, 0, BusScale::kPerMilleRated),
    signal_decl::at("state", "-", "supervisor state name", SignalSource::kSupervisor, 0),
    // The planting monitor (firmware/sensing/planting_monitor.h): the columns this project adds.
    signal_decl::at("warnings", "bits", "alarms holding, a bit each (see Alarms below)",
                    SignalSource::kWarnings, 0),
    signal_decl::monitored("seedlings", "count", "seedlings the photo-eye saw since start", 0,
                           &PlantingFigures::seedlings),
    signal_decl::monitored("seedlings_per_m", "1/m", "seedlings in the last metre travelled", 0,
                           &PlantingFigures::per_m),
    signal_decl::monitored("spacing_mm", "mm", "the last spacing, by the soil wheel", 1,
                           &PlantingFigures::spacing_mm),
    signal_decl::monitored("spacing_mean_mm", "mm", "mean spacing since start", 2,
                           &PlantingFigures::spacing_mean_mm),
    signal_decl::monitored("spacing_cv", "1", "spacing SD / mean since start", 4,
                           &PlantingFigures::spacing_cv),
    signal_decl::monitored("skips", "count", "spacings over 1.5x the target since start", 0,
                           &PlantingFigures::skips),
    signal_decl::monitored("multiples", "count", "spacings at most 0.5x the target since start", 0,
                           &PlantingFigures::multiples),
    signal_decl::monitored("singulation_pct", "%", "100 - skips - multiples, in % of spacings", 2,
                           &PlantingFigures::singulation_pct),
    signal_decl::monitored("damage_seen", "count",
                           "stems whose wall the clamp saw give way since start", 0,
                           &PlantingFigures::damage_seen),
    // The operator's set-point, which the depth command ramps to (firmware/control/
    // furrow_depth_loop.h): a change from the console shows here on the next tick.
    signal_decl::commanded("depth_target_mm", "mm", "furrow depth target (operator's set-point)", 1,
                           &MachineCommand::depth_target_mm),
    // The ground as the sigma loop sees it (firmware/sensing/ground_fusion.h).
    signal_decl::gnss("v_gnss", "m/s", "speed over ground in the GNSS receiver's newest fix", 4,
                      &MachineState::v_gnss_mps),
    signal_decl::commanded("ground_speed", "m/s",
                           "ground speed the sigma loop uses: the wheel's, slip corrected", 5,
                           &MachineCommand::ground_speed_mps),
    signal_decl::commanded("slip_est", "1",
                           "the soil wheel's slip beyond its calibration, estimated", 4,
                           &MachineCommand::slip_est),
    // The antenna's place (WGS 84), for the as-planted map; 0, 0 with no fix in the last second.
    signal_decl::gnss("lat_deg", "deg", "latitude of the GNSS antenna's newest fix", 8,
                      &MachineState::lat_deg),
    signal_decl::gnss("lon_deg", "deg", "longitude of the GNSS antenna's newest fix", 8,
                      &MachineState::lon_deg),
    // In the process image, not a recording column.
    signal_decl::commanded("clamp_pos_cmd_mm", "mm", "roller position command", 4,
                           &MachineCommand::clamp_pos_cmd_mm, NodeRole::kRollerActuator,
                           signal_decl::c402::kTargetPosition, BusScale::kPerCount, false),
};

// The index in kSignals of a recording column, kSignals.size() when there is none.
constexpr std::size_t signal_index(std::string_view column) {
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    if (kSignals[i].column == column) return i;
  }
  return kSignals.size();
}
// The declaration of a recording column, or nullptr.
constexpr const SignalDecl* find_signal(std::string_view column) {
  const std::size_t i = signal_index(column);
  return i < kSignals.size() ? &kSignals[i] : nullptr;
}
// A column the code names itself, found at compile time (a hot path does not search on every
// tick); a misspelt name does not compile. By index: the sanitizers' null checks make a
// pointer comparison no constant expression.
consteval const SignalDecl& known_signal(std::string_view column) {
  const std::size_t i = signal_index(column);
  if (i >= kSignals.size()) throw "not a column of the signal table";
  return kSignals[i];
}
// The bus signal carried by (role, index, sub), or nullptr.
const SignalDecl* find_bus_signal(NodeRole role, std::uint16_t index, std::uint8_t sub);

}  // namespace planter
