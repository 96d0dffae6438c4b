#pragma once
// Reconnect and resume after the controller's own CAN link went down and came back (a cable
// pulled and pushed in, an adapter re-enumerated). Opt-in per board: only faults the lost link
// explains by itself are reset, once the link has been up for a settling time; anything else
// still needs the operator. Pure logic: the link state comes in through the process image.
#include <cstdint>

#include "firmware/supervisor/supervisor.h"

namespace planter {

struct LinkRecoveryConfig {
  bool enabled = false;
  bool resume_running = false;            // the machine is meant to run, not wait in ready
  std::int64_t settle_ns = 500'000'000;   // the link must be up this long before a reset
  std::int64_t retry_ns = 500'000'000;    // between two resets
  std::int64_t quiet_ns = 2'000'000'000;  // up this long without a fault: nothing to recover
};

struct LinkRecoveryInputs {
  std::int64_t now_ns = 0;
  bool link_up = true;
  std::uint32_t link_downs = 0;
  SupervisorState state = SupervisorState::kBoot;
  std::uint32_t latched_faults = 0;
};

class LinkRecovery {
 public:
  explicit LinkRecovery(const LinkRecoveryConfig& config) : cfg_(config) {}

  // True when a fault reset should be requested on this tick.
  bool update(const LinkRecoveryInputs& in);
  [[nodiscard]] bool pending() const { return pending_; }
  [[nodiscard]] std::uint32_t resets() const { return resets_; }

 private:
  LinkRecoveryConfig cfg_;
  bool primed_ = false;  // link_downs_seen_ holds the count at the first tick
  std::uint32_t link_downs_seen_ = 0;
  bool pending_ = false;
  bool reset_done_ = false;
  std::int64_t up_since_ns_ = -1;
  std::int64_t next_reset_ns_ = 0;
  std::uint32_t resets_ = 0;
};

}  // namespace planter
