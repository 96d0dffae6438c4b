#include "firmware/canopen/cia402.h"

namespace planter::canopen::cia402 {

State decode_state(std::uint16_t sw) {
  if ((sw & 0x4F) == 0x00) return State::kNotReadyToSwitchOn;
  if ((sw & 0x4F) == 0x40) return State::kSwitchOnDisabled;
  if ((sw & 0x4F) == 0x0F) return State::kFaultReactionActive;
  if ((sw & 0x4F) == 0x08) return State::kFault;
  switch (sw & 0x6F) {
    case 0x21:
      return State::kReadyToSwitchOn;
    case 0x23:
      return State::kSwitchedOn;
    case 0x27:
      return State::kOperationEnabled;
    case 0x07:
      return State::kQuickStopActive;
    default:
      return State::kNotReadyToSwitchOn;
  }
}

std::uint16_t encode_state(State s) {
  switch (s) {
    case State::kNotReadyToSwitchOn:
      return 0x0000;
    case State::kSwitchOnDisabled:
      return 0x0040;
    case State::kReadyToSwitchOn:
      return 0x0021;
    case State::kSwitchedOn:
      return 0x0023;
    case State::kOperationEnabled:
      return 0x0027;
    case State::kQuickStopActive:
      return 0x0007;
    case State::kFaultReactionActive:
      return 0x000F;
    case State::kFault:
      return 0x0008;
  }
  return 0;
}

const char* state_name(State s) {
  switch (s) {
    case State::kNotReadyToSwitchOn:
      return "not ready to switch on";
    case State::kSwitchOnDisabled:
      return "switch on disabled";
    case State::kReadyToSwitchOn:
      return "ready to switch on";
    case State::kSwitchedOn:
      return "switched on";
    case State::kOperationEnabled:
      return "operation enabled";
    case State::kQuickStopActive:
      return "quick stop active";
    case State::kFaultReactionActive:
      return "fault reaction active";
    case State::kFault:
      return "fault";
  }
  return "?";
}

std::uint16_t next_controlword(State current, State wanted, bool& fault_reset_phase) {
  using namespace controlword;
  if (current == State::kFault) {
    fault_reset_phase = !fault_reset_phase;
    return fault_reset_phase ? kFaultReset : kDisableVoltage;
  }
  fault_reset_phase = false;
  if (wanted == State::kQuickStopActive) {
    // Quick stop from operation enabled; anywhere else, removing voltage is at least as safe.
    return current == State::kOperationEnabled || current == State::kQuickStopActive
               ? kQuickStop
               : kDisableVoltage;
  }
  if (wanted == State::kSwitchOnDisabled) return kDisableVoltage;
  switch (current) {
    case State::kNotReadyToSwitchOn:
    case State::kFaultReactionActive:
      return kDisableVoltage;
    case State::kSwitchOnDisabled:
    case State::kQuickStopActive:
      return kShutdown;
    case State::kReadyToSwitchOn:
      return kSwitchOn;
    case State::kSwitchedOn:
      return wanted == State::kOperationEnabled ? kEnableOperation : kSwitchOn;
    case State::kOperationEnabled:
      return wanted == State::kOperationEnabled ? kEnableOperation : kSwitchOn;
    case State::kFault:
      break;
  }
  return kDisableVoltage;
}

State apply_controlword(State s, std::uint16_t cw, std::uint16_t previous) {
  const bool fault_reset_edge = (cw & 0x80) != 0 && (previous & 0x80) == 0;
  if (s == State::kFault) return fault_reset_edge ? State::kSwitchOnDisabled : s;
  if (s == State::kFaultReactionActive || s == State::kNotReadyToSwitchOn) return s;
  const std::uint16_t c = cw & 0x8F;
  const bool disable_voltage = (c & 0x02) == 0;
  const bool quick_stop = (c & 0x06) == 0x02;
  if (disable_voltage) return State::kSwitchOnDisabled;
  if (quick_stop) {
    return s == State::kOperationEnabled || s == State::kQuickStopActive ? State::kQuickStopActive
                                                                         : State::kSwitchOnDisabled;
  }
  const std::uint16_t shutdown_mask = c & 0x87;
  if (shutdown_mask == 0x06) {
    return s == State::kQuickStopActive ? State::kSwitchOnDisabled : State::kReadyToSwitchOn;
  }
  if ((c & 0x8F) == 0x07) {
    if (s == State::kReadyToSwitchOn || s == State::kOperationEnabled) return State::kSwitchedOn;
    return s == State::kQuickStopActive ? State::kQuickStopActive : s;
  }
  if ((c & 0x8F) == 0x0F) {
    if (s == State::kSwitchedOn || s == State::kOperationEnabled) return State::kOperationEnabled;
    if (s == State::kReadyToSwitchOn) return State::kSwitchedOn;  // 3 then 4, one step per word
    if (s == State::kQuickStopActive) return State::kQuickStopActive;
  }
  return s;
}

}  // namespace planter::canopen::cia402
