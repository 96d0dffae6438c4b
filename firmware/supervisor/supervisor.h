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
// Faults a lost CAN link causes by itself (link_recovery.h resets only these).
constexpr std::uint32_t kLinkLoss = kHeartbeatLost | kPdoStale | kBusOff;
// The name of fault bit `bit` (0-based), in the operator's words; "" past the last.
const char* name(int bit);
}  // namespace fault

// What the operator should see but the machine may go on with (bit set).
namespace warning {
constexpr std::uint32_t kEmptyBelt = 1u << 0;  // the photo-eye saw N clamps pass empty in a row
// A loop that cannot hold its goal (firmware/control/loop_goals.h) says which and why.
constexpr std::uint32_t kTooFastForDisc = 1u << 1;     // sigma v / R above the disc's top speed
constexpr std::uint32_t kDiscLagging = 1u << 2;        // the disc behind its angle reference
constexpr std::uint32_t kClampShort = 1u << 3;         // the roller at its travel, force short
constexpr std::uint32_t kLoadCellDisagrees = 1u << 4;  // load cell against roller position
constexpr std::uint32_t kClampAtCeiling = 1u << 5;     // force held back at the ceiling
constexpr std::uint32_t kSeedlingsFalling = 1u << 6;   // empty clamps after a weak grip
constexpr std::uint32_t kDepthUnreachable = 1u << 7;   // the opener at its end stop, depth short
constexpr std::uint32_t kDepthOffBand = 1u << 8;       // the measured depth out of its band
constexpr std::uint32_t kStemGaveWay = 1u << 9;        // a stem's wall collapsed in the clamp
constexpr std::uint32_t kGnssLost = 1u << 10;          // ground speed from the soil wheel alone
constexpr int kCount = 11;
// Which alarms speak for which loop (the disturbance suite's verdicts read these).
constexpr std::uint32_t kSigmaAlarms = kTooFastForDisc | kDiscLagging | kGnssLost;
constexpr std::uint32_t kClampAlarms =
    kClampShort | kLoadCellDisagrees | kClampAtCeiling | kSeedlingsFalling | kStemGaveWay;
constexpr std::uint32_t kDepthAlarms = kDepthUnreachable | kDepthOffBand;
// The name of warning bit `bit` (0-based), in the operator's words; "" past the last.
const char* name(int bit);
}  // namespace warning

struct SupervisorConfig {
  std::int64_t overrun_threshold_ns = 15'000'000;  // a tick later than this is an overrun
  std::uint32_t overruns_to_fault = 3;             // consecutive overruns before a fault
  double force_plausible_min_N = -20.0;
  double force_plausible_max_N = 400.0;
  double ground_speed_plausible_max_mps = 1.0;
  std::int64_t pdo_stale_ns = 100'000'000;  // no fresh TPDO for this long -> fault
  std::int64_t boot_timeout_ns = 5'000'000'000;
  double stopped_omega_radps = 0.01;
  // The disc may turn this much faster than sigma * v / R (starts, angle catch-up) for at most
  // disc_implausible_ns before a fault: beyond that a scale, wiring or control error is turning
  // the disc against the ground (at standstill it throws seedlings on the headland).
  double disc_plausible_margin_radps = 0.3;
  std::int64_t disc_implausible_ns = 1'000'000'000;
};

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
