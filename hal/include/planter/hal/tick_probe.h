#pragma once
// Where a control tick spends its time. The controller says when each phase of its tick ends;
// what stamps it is the board's business (planterd: the monotonic clock into a fixed ring that
// is dumped on an overrun). The simulator passes none: lockstep time is not wall time.
#include <cstdint>

namespace planter::hal {

enum class TickPhase : std::uint8_t {
  kReceive,   // bus frames, encoder edges and process values read
  kControl,   // supervisor, commissioning and the loops decided
  kTransmit,  // RPDOs and SYNC sent
  kHandOff,   // telemetry handed to the recorder and status readers (after the controller)
};
inline constexpr int kTickPhaseCount = 4;

class TickProbe {
 public:
  virtual ~TickProbe() = default;
  virtual void phase_done(TickPhase phase) = 0;
};

}  // namespace planter::hal
