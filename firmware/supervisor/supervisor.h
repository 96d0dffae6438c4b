#pragma once
// The machine's top-level state and its fault decisions. Pure logic: inputs in, state out.
#include <cstdint>

namespace planter {

enum class SupervisorState : std::uint8_t {
  kBoot,
  kCommissioning,
  kReady,
  kRunning,
  kStopping,
  kFault,
  kEStop,
};
const char* supervisor_state_name(SupervisorState state);

// Why the supervisor went to fault (bit set; several can hold).
namespace fault {
constexpr std::uint32_t kHeartbeatLost = 1u << 0;
constexpr std::uint32_t kDriveFault = 1u << 1;
constexpr std::uint32_t kEmergency = 1u << 2;
constexpr std::uint32_t kSensorImplausible = 1u << 3;
constexpr std::uint32_t kPdoStale = 1u << 4;
constexpr std::uint32_t kOverrun = 1u << 5;
constexpr std::uint32_t kBootFailed = 1u << 6;
constexpr std::uint32_t kBusOff = 1u << 7;
constexpr std::uint32_t kUnexpectedBootUp = 1u << 8;
constexpr int kCount = 9;
// The name of fault bit `bit` (0-based), in the operator's words; "" past the last.
const char* name(int bit);
}  // namespace fault

struct SupervisorInputs {
  bool estop = false;
  bool nodes_ready = false;  // every node booted, configured, operational, drives enabled
  std::uint32_t faults = 0;  // fault:: bits seen this tick
  bool disc_stopped = false;
  bool run_requested = false;
  bool stop_requested = false;
  bool reset_requested = false;
};

class Supervisor {
 public:
  SupervisorState update(const SupervisorInputs& in);
  [[nodiscard]] SupervisorState state() const { return state_; }
  [[nodiscard]] std::uint32_t latched_faults() const { return latched_; }
  [[nodiscard]] std::uint32_t transitions() const { return transitions_; }

 private:
  void go(SupervisorState next);
  SupervisorState state_ = SupervisorState::kBoot;
  std::uint32_t latched_ = 0;
  std::uint32_t transitions_ = 0;
};

}  // namespace planter
