#pragma once
// What an operator may ask of the machine at run time (the console, planterd's signals), and
// the controller's answer. A command never goes around the supervisor: the e-stop, a fault and
// the commissioning gate each win over it, and a set-point out of its range changes nothing.
#include <cstdint>

namespace planter {

enum class CommandKind : std::uint8_t {
  kRun,            // start planting
  kStop,           // stop planting (the disc is brought to rest)
  kFaultReset,     // clear latched faults whose cause is gone
  kSetDepth,       // furrow depth target, mm
  kSetClampForce,  // clamp force set-point, N
};

enum class CommandOutcome : std::uint8_t {
  kAccepted,
  kOutOfRange,       // the value is outside the set-point's range: nothing changed
  kRefusedEStop,     // the e-stop is held
  kRefusedFault,     // the machine is in fault: reset it first
  kRefusedNotReady,  // the nodes are still booting, or the machine is not ready to run
  kRefusedGate,      // not commissioned (planter-can check --mark-commissioned)
};

struct OperatorCommand {
  CommandKind kind = CommandKind::kStop;
  double value = 0.0;  // for the set-points, in the unit named by the kind
};

// The operator's words for an outcome (what happened and what to do).
const char* command_outcome_text(CommandOutcome outcome);
const char* command_kind_name(CommandKind kind);

}  // namespace planter
