#pragma once
// Plain data the controller is built from. Filled by the board-file loader (config/) at
// init; the firmware never parses files.
#include <array>
#include <cstdint>

#include "firmware/canopen/pdo.h"

namespace planter {

enum class NodeRole : std::uint8_t {
  kDiscDrive = 0,
  kRollerActuator,
  kDepthActuator,
  kForceSensor
};
constexpr std::size_t kNodeCount = 4;
const char* node_role_name(NodeRole role);

struct NodeConfig {
  NodeRole role = NodeRole::kDiscDrive;
  std::uint8_t node_id = 0;
  std::uint16_t profile = 402;     // low 16 bits of 0x1000
  std::uint32_t vendor_id = 0;     // 0x1018:1; 0 = do not check
  std::uint32_t product_code = 0;  // 0x1018:2; 0 = do not check
  // rpdo[k]: master -> node (0x1400+k/0x1600+k); tpdo[k]: node -> master (0x1800+k/0x1A00+k).
  std::array<canopen::PdoMapping, 4> rpdo{};
  std::array<canopen::PdoMapping, 4> tpdo{};
  double counts_per_unit = 1.0;  // drive position counts per rad (disc) or per mm (actuators)
  double zero_counts = 0.0;      // sensors: the reading at zero load (tare, from calibration)
  double rated_torque = 1.0;     // 0x6077 per-mille base: N*m for the disc, N for actuators
  double profile_velocity_units_per_s = 0.0;  // position drives: 0x6081, in rad/s or mm/s
};

struct CanConfig {
  std::uint32_t bitrate_bps = 500000;
  std::int64_t sync_period_ns = 10'000'000;
  std::uint16_t heartbeat_producer_ms = 100;
  double heartbeat_consumer_factor = 1.5;  // consumer timeout = factor * producer period
  std::int64_t sdo_timeout_ns = 100'000'000;
};

struct EncoderConfig {
  std::uint32_t counts_per_rev = 4096;     // after x4 decoding
  double wheel_radius_m = 0.15;            // effective rolling radius (calibrated)
  std::int64_t glitch_filter_ns = 20'000;  // edges closer than this on one line are ignored
  std::int64_t speed_window_ns = 200'000'000;
};

struct SigmaLoopConfig {
  double sigma = 1.5;
  double disc_radius_m = 0.300;
  double angle_gain_per_s = 3.0;  // disc angle error -> speed correction
  double omega_max_radps = 1.2;
};

struct ClampLoopConfig {
  double setpoint_N = 90.0;
  double ceiling_N = 120.0;
  double ramp_N_per_s = 60.0;  // set-point ramp at start
  double kp_mm_per_N = 0.01;
  double ki_mm_per_Ns = 0.08;
  double position_min_mm = 0.0;
  double position_max_mm = 12.0;
  double release_position_mm = 0.0;  // roller position when not clamping
  // Nominal clamp model used for feed-forward and the ceiling guard: F = k (x - x0)^n.
  double model_k_N = 14.85;
  double model_x0_mm = 2.0;
  double model_n = 1.3;
};

struct DepthLoopConfig {
  double target_mm = 102.0;
  double rate_mm_per_s = 20.0;
  double ki_per_s = 0.5;
  double trim_max_mm = 15.0;
  double min_mm = 0.0;
  double max_mm = 170.0;
  double raised_mm = 0.0;  // opener position out of the ground
};

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

struct ControllerConfig {
  CanConfig can;
  std::array<NodeConfig, kNodeCount> nodes{};
  EncoderConfig encoder;
  SigmaLoopConfig sigma;
  ClampLoopConfig clamp;
  DepthLoopConfig depth;
  SupervisorConfig supervisor;
  bool estop_active_low = true;

  [[nodiscard]] const NodeConfig& node(NodeRole r) const {
    return nodes[static_cast<std::size_t>(r)];
  }
};

}  // namespace planter
