#include "firmware/supervisor/supervisor.h"

namespace planter {

const char* fault::name(int bit) {
  static constexpr const char* kNames[kCount] = {
      "heartbeat lost", "drive fault", "emergency (EMCY)", "implausible sensor", "stale PDO",
      "loop overrun",   "boot failed", "bus-off",          "unexpected boot-up"};
  return bit >= 0 && bit < kCount ? kNames[bit] : "";
}

const char* warning::name(int bit) {
  // What the operator reads; the console adds what to do (console_page.html's advice), and
  // docs/recording-format.md lists them by bit.
  static constexpr const char* kNames[kCount] = {"empty belt: clamps passing with no seedling",
                                                 "too fast for the disc",
                                                 "disc lagging the ground",
                                                 "clamp cannot reach its force",
                                                 "load cell disagrees with the roller",
                                                 "clamp force at its ceiling",
                                                 "seedlings falling from the clamp",
                                                 "opener at its end stop",
                                                 "furrow depth off by more than 2 mm",
                                                 "a stem gave way in the clamp",
                                                 "no GNSS fix: speed from the soil wheel alone"};
  return bit >= 0 && bit < kCount ? kNames[bit] : "";
}

const char* supervisor_state_name(SupervisorState s) {
  switch (s) {
    case SupervisorState::kBoot:
      return "boot";
    case SupervisorState::kCommissioning:
      return "commissioning";
    case SupervisorState::kReady:
      return "ready";
    case SupervisorState::kRunning:
      return "running";
    case SupervisorState::kStopping:
      return "stopping";
    case SupervisorState::kFault:
      return "fault";
    case SupervisorState::kEStop:
      return "estop";
  }
  return "?";
}

void Supervisor::go(SupervisorState next) {
  if (next != state_) {
    state_ = next;
    ++transitions_;
  }
}

SupervisorState Supervisor::update(const SupervisorInputs& in) {
  if (in.estop) {
    go(SupervisorState::kEStop);
    return state_;
  }
  const bool operating = state_ == SupervisorState::kReady || state_ == SupervisorState::kRunning ||
                         state_ == SupervisorState::kStopping;
  if (operating && in.faults != 0) {
    latched_ |= in.faults;
    go(SupervisorState::kFault);
    return state_;
  }
  switch (state_) {
    case SupervisorState::kBoot:
      go(SupervisorState::kCommissioning);
      break;
    case SupervisorState::kCommissioning:
      if ((in.faults & fault::kBootFailed) != 0) {
        latched_ |= in.faults;
        go(SupervisorState::kFault);
      } else if (in.nodes_ready) {
        go(SupervisorState::kReady);
      }
      break;
    case SupervisorState::kReady:
      if (in.run_requested) go(SupervisorState::kRunning);
      break;
    case SupervisorState::kRunning:
      if (in.stop_requested) go(SupervisorState::kStopping);
      break;
    case SupervisorState::kStopping:
      if (in.disc_stopped) go(SupervisorState::kReady);
      break;
    case SupervisorState::kFault:
    case SupervisorState::kEStop:
      // Leaving needs an operator reset with the cause gone; nodes are then booted again.
      if (in.reset_requested && in.faults == 0) {
        latched_ = 0;
        go(SupervisorState::kCommissioning);
      }
      break;
  }
  return state_;
}

}  // namespace planter
