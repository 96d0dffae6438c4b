#include "firmware/controller/operator_command.h"

namespace planter {

const char* command_outcome_text(CommandOutcome outcome) {
  switch (outcome) {
    case CommandOutcome::kAccepted:
      return "accepted";
    case CommandOutcome::kOutOfRange:
      return "out of range: nothing changed";
    case CommandOutcome::kRefusedEStop:
      return "refused: the e-stop is held; release it, then reset";
    case CommandOutcome::kRefusedFault:
      return "refused: the machine is in fault; clear the cause, then reset";
    case CommandOutcome::kRefusedNotReady:
      return "refused: the machine is not ready (the nodes are booting or stopping)";
    case CommandOutcome::kRefusedGate:
      return "refused: not commissioned; run planter-can check --mark-commissioned";
  }
  return "unknown";
}

const char* command_kind_name(CommandKind kind) {
  switch (kind) {
    case CommandKind::kRun:
      return "run";
    case CommandKind::kStop:
      return "stop";
    case CommandKind::kFaultReset:
      return "fault_reset";
    case CommandKind::kSetDepth:
      return "set_depth_mm";
    case CommandKind::kSetClampForce:
      return "set_clamp_force_N";
  }
  return "unknown";
}

}  // namespace planter
