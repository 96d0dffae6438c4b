#pragma once
// Refused logins, counted and said in the audit log as a summary instead of a line (and an
// fdatasync) each (issue 28, item 3): a flood of wrong secrets from the farm's network then
// grows the log by one line a period, not by a line per request. The first refusal after a
// quiet period is said at once, in its own words; the rest are counted until the period has
// passed or anything else is audited, whichever comes first, so the log keeps its order.
#include <chrono>
#include <climits>
#include <cstdint>
#include <mutex>
#include <optional>
#include <set>
#include <string>

namespace planter::console {

// The console's clock (monotonic nanoseconds): the sessions' and the tally's.
inline std::int64_t console_now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// One audit line: the refusal itself ("login", value "-") or a summary ("login_refused", value
// how many).
struct RefusalSummary {
  std::string address;  // the one address, or "-" for several
  std::string what;
  std::string value;
  std::string words;
};

class RefusedLoginTally {
 public:
  explicit RefusedLoginTally(double period_s)
      : period_ns_(static_cast<std::int64_t>(period_s * 1e9)) {}

  // A refusal now; what to write, if anything: the refusal itself after a quiet period, or the
  // summary of the period that has passed (this refusal included).
  std::optional<RefusalSummary> add(const std::string& address, const std::string& words,
                                    std::int64_t now_ns);
  // The summary of the refusals not yet said, if any (before another line is audited).
  std::optional<RefusalSummary> take(std::int64_t now_ns);

 private:
  std::optional<RefusalSummary> summary_locked(std::int64_t now_ns);
  std::int64_t period_ns_;
  std::mutex mutex_;
  std::int64_t said_ns_ = INT64_MIN / 2;  // when a line was last written
  long pending_ = 0, pending_limited_ = 0;
  std::set<std::string> addresses_;  // of the pending refusals, at most kAddressesMax
  bool more_addresses_ = false;
  std::int64_t first_ns_ = 0;
};

}  // namespace planter::console
