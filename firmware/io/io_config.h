#pragma once
// What the I/O layer is built from: the nodes on the bus, the bus itself and the soil-wheel
// encoder. Filled by the board-file loader (config/) at init; the firmware never parses files.
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

// The soil wheel's scale, declared once: one count is this much ground (2 pi r / counts per
// revolution), and the radius a measured counts-per-metre gives (planter-can calibrate).
constexpr double kTwoPi = 6.283185307179586;
constexpr double metres_per_count(const EncoderConfig& e) {
  return kTwoPi * e.wheel_radius_m / static_cast<double>(e.counts_per_rev);
}
constexpr double wheel_radius_for_counts_per_m(std::uint32_t counts_per_rev, double counts_per_m) {
  return static_cast<double>(counts_per_rev) / (kTwoPi * counts_per_m);
}

}  // namespace planter
