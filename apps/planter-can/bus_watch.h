#pragma once
// Passive listening: what each node says (boot-up, heartbeat state and period, EMCY) and how
// often each COB-ID appears, with bus load. Shared by scan, monitor and check.
#include <array>
#include <cstdint>
#include <map>

#include "planter/hal/can_frame.h"

namespace planter::cantool {

struct NodeSeen {
  bool seen = false;  // any frame from this node
  bool boot_up = false;
  std::uint8_t state = 0xFF;  // last heartbeat state; 0xFF = none
  std::uint32_t heartbeats = 0;
  std::int64_t first_heartbeat_ns = 0;
  std::int64_t last_heartbeat_ns = 0;
  std::int64_t max_heartbeat_gap_ns = 0;
  std::uint32_t emcy_count = 0;
  std::uint16_t last_emcy_code = 0;
  std::uint32_t pdo_frames = 0;
};

struct CobStats {
  std::uint64_t count = 0;
  std::int64_t first_ns = 0;
  std::int64_t last_ns = 0;
  std::int64_t max_gap_ns = 0;
  hal::CanFrame last;  // the newest frame on this COB-ID
  // Mean frames per second between the first and the last frame.
  [[nodiscard]] double rate_hz() const;
};

class BusWatch {
 public:
  void on_frame(const hal::CanFrame& frame, std::int64_t now_ns);
  void start(std::int64_t now_ns) { start_ns_ = now_ns; }

  [[nodiscard]] const NodeSeen& node(std::uint8_t id) const { return nodes_[id & 0x7F]; }
  [[nodiscard]] const std::map<std::uint16_t, CobStats>& cobs() const { return cobs_; }
  [[nodiscard]] std::uint64_t frames() const { return frames_; }
  [[nodiscard]] std::uint64_t error_frames() const { return error_frames_; }
  [[nodiscard]] std::uint64_t bits() const { return bits_; }
  // Share of the bus the frames seen since start() took, in percent.
  [[nodiscard]] double bus_load_pct(std::uint32_t bitrate_bps, std::int64_t now_ns) const;

 private:
  std::array<NodeSeen, 128> nodes_{};
  std::map<std::uint16_t, CobStats> cobs_;
  std::uint64_t frames_ = 0;
  std::uint64_t error_frames_ = 0;
  std::uint64_t bits_ = 0;
  std::int64_t start_ns_ = 0;
};

}  // namespace planter::cantool
