#include "firmware/supervisor/link_recovery.h"

namespace planter {

bool LinkRecovery::update(const LinkRecoveryInputs& in) {
  if (!primed_) {
    primed_ = true;
    link_downs_seen_ = in.link_downs;
  }
  if (!cfg_.enabled) return false;
  if (in.link_downs != link_downs_seen_) {
    link_downs_seen_ = in.link_downs;
    pending_ = true;
    reset_done_ = false;
    up_since_ns_ = -1;
  }
  if (!pending_) return false;
  if (!in.link_up) {
    up_since_ns_ = -1;
  } else if (up_since_ns_ < 0) {
    up_since_ns_ = in.now_ns;
  }
  const bool up_settled = up_since_ns_ >= 0 && in.now_ns - up_since_ns_ >= cfg_.settle_ns;
  const bool only_link_faults = (in.latched_faults & ~fault::kLinkLoss) == 0;
  bool reset = false;
  if (in.state == SupervisorState::kFault && only_link_faults && up_settled &&
      in.now_ns >= next_reset_ns_) {
    reset = true;
    next_reset_ns_ = in.now_ns + cfg_.retry_ns;
    reset_done_ = true;
    ++resets_;
  }
  // Done once back after a reset, or when the loss caused no fault at all.
  const bool back = in.state == SupervisorState::kRunning ||
                    (in.state == SupervisorState::kReady && !cfg_.resume_running);
  if (back && (reset_done_ || (up_since_ns_ >= 0 && in.now_ns - up_since_ns_ > cfg_.quiet_ns)))
    pending_ = false;
  if (in.state == SupervisorState::kFault && !only_link_faults) pending_ = false;
  return reset;
}

}  // namespace planter
