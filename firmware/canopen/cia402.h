#pragma once
// CiA 402 drive profile: the power state machine seen from the master (controlword to send
// for a wanted state) and from the drive (statusword after a controlword).
#include <cstdint>

namespace planter::canopen::cia402 {

constexpr std::uint16_t kControlword = 0x6040;
constexpr std::uint16_t kStatusword = 0x6041;
constexpr std::uint16_t kModesOfOperation = 0x6060;
constexpr std::uint16_t kModesDisplay = 0x6061;
constexpr std::uint16_t kErrorCode = 0x603F;
constexpr std::uint16_t kPositionActual = 0x6064;
constexpr std::uint16_t kVelocityActual = 0x606C;
constexpr std::uint16_t kTorqueActual = 0x6077;
constexpr std::uint16_t kTargetPosition = 0x607A;
constexpr std::uint16_t kProfileVelocity = 0x6081;
constexpr std::uint16_t kProfileAcceleration = 0x6083;
constexpr std::uint16_t kTargetVelocity = 0x60FF;
constexpr std::uint16_t kSupportedModes = 0x6502;

constexpr std::int8_t kModeProfilePosition = 1;
constexpr std::int8_t kModeProfileVelocity = 3;
constexpr std::int8_t kModeHoming = 6;

enum class State : std::uint8_t {
  kNotReadyToSwitchOn,
  kSwitchOnDisabled,
  kReadyToSwitchOn,
  kSwitchedOn,
  kOperationEnabled,
  kQuickStopActive,
  kFaultReactionActive,
  kFault,
};

namespace controlword {
constexpr std::uint16_t kShutdown = 0x0006;
constexpr std::uint16_t kSwitchOn = 0x0007;
constexpr std::uint16_t kEnableOperation = 0x000F;
constexpr std::uint16_t kQuickStop = 0x0002;
constexpr std::uint16_t kDisableVoltage = 0x0000;
constexpr std::uint16_t kFaultReset = 0x0080;
constexpr std::uint16_t kNewSetPoint = 0x0010;        // profile position: bit 4
constexpr std::uint16_t kChangeImmediately = 0x0020;  // profile position: bit 5
}  // namespace controlword

namespace statusword {
constexpr std::uint16_t kTargetReached = 0x0400;
constexpr std::uint16_t kSetPointAcknowledge = 0x1000;
}  // namespace statusword

State decode_state(std::uint16_t statusword);
std::uint16_t encode_state(State state);  // the state bits of a statusword
const char* state_name(State state);

// Master side: the controlword that moves a drive one step towards `wanted`
// (kOperationEnabled, kSwitchedOn, kQuickStopActive or kSwitchOnDisabled).
// `fault_reset_phase` alternates so a fault reset makes the rising edge the drive needs.
std::uint16_t next_controlword(State current, State wanted, bool& fault_reset_phase);

// Drive side: the new state after a controlword (CiA 402 transitions 2-16).
State apply_controlword(State current, std::uint16_t controlword,
                        std::uint16_t previous_controlword);

}  // namespace planter::canopen::cia402
