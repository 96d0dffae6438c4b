#include "console/refused_logins.h"

namespace planter::console {
namespace {
constexpr std::size_t kAddressesMax = 1024;  // what the summary names counts; memory bounded
}

std::optional<RefusalSummary> RefusedLoginTally::add(const std::string& address,
                                                     const std::string& words,
                                                     std::int64_t now_ns) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (pending_ == 0 && now_ns - said_ns_ >= period_ns_) {
    said_ns_ = now_ns;
    return RefusalSummary{address, "login", "-", words};
  }
  if (pending_ == 0) first_ns_ = now_ns;
  ++pending_;
  if (words.rfind("too many", 0) == 0) ++pending_limited_;
  if (addresses_.size() < kAddressesMax)
    addresses_.insert(address);
  else if (addresses_.count(address) == 0)
    more_addresses_ = true;
  if (now_ns - said_ns_ >= period_ns_) return summary_locked(now_ns);
  return std::nullopt;
}

std::optional<RefusalSummary> RefusedLoginTally::take(std::int64_t now_ns) {
  std::lock_guard<std::mutex> lock(mutex_);
  return summary_locked(now_ns);
}

std::optional<RefusalSummary> RefusedLoginTally::summary_locked(std::int64_t now_ns) {
  if (pending_ == 0) return std::nullopt;
  RefusalSummary s;
  s.address = addresses_.size() == 1 && !more_addresses_ ? *addresses_.begin() : "-";
  s.what = "login_refused";
  s.value = std::to_string(pending_);
  s.words = std::to_string(pending_) + " refused logins (" +
            std::to_string(pending_ - pending_limited_) + " wrong secret, " +
            std::to_string(pending_limited_) + " too many wrong secrets) from " +
            (more_addresses_ ? "more than " : "") + std::to_string(addresses_.size()) +
            " addresses over " + std::to_string((now_ns - first_ns_) / 1'000'000'000) + " s";
  pending_ = pending_limited_ = 0;
  addresses_.clear();
  more_addresses_ = false;
  said_ns_ = now_ns;
  return s;
}

}  // namespace planter::console
