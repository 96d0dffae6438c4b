#pragma once
// Watches one node's heartbeat (CiA 301 heartbeat consumer).
#include <cstdint>

#include "firmware/canopen/cob_id.h"

namespace planter::canopen {

class HeartbeatConsumer {
 public:
  explicit HeartbeatConsumer(std::int64_t timeout_ns = 0) : timeout_ns_(timeout_ns) {}
  void set_timeout_ns(std::int64_t timeout_ns) { timeout_ns_ = timeout_ns; }

  void on_heartbeat(std::uint8_t state_byte, std::int64_t now_ns) {
    state_ = static_cast<NmtState>(state_byte);
    last_ns_ = now_ns;
    seen_ = true;
    if (state_ == NmtState::kBootUp) ++boot_ups_;
  }
  // Starts the watch from now (used when the node is started).
  void arm(std::int64_t now_ns) {
    last_ns_ = now_ns;
    armed_ = true;
  }
  void disarm() { armed_ = false; }
  [[nodiscard]] bool timed_out(std::int64_t now_ns) const {
    return armed_ && timeout_ns_ > 0 && now_ns - last_ns_ > timeout_ns_;
  }
  [[nodiscard]] NmtState state() const { return state_; }
  [[nodiscard]] bool seen() const { return seen_; }
  [[nodiscard]] std::uint32_t boot_ups() const { return boot_ups_; }
  [[nodiscard]] std::int64_t last_ns() const { return last_ns_; }

 private:
  std::int64_t timeout_ns_;
  std::int64_t last_ns_ = 0;
  NmtState state_ = NmtState::kUnknown;
  bool seen_ = false;
  bool armed_ = false;
  std::uint32_t boot_ups_ = 0;
};

}  // namespace planter::canopen
