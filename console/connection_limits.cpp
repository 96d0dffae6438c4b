#include "console/connection_limits.h"

#include <algorithm>

namespace planter::console {

bool ConnectionLimits::is_operator(const std::string& address) const {
  return std::find(operators_.begin(), operators_.end(), address) != operators_.end();
}

Ticket ConnectionLimits::admit(const std::string& address) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto at = by_address_.find(address);
  const std::size_t held = at == by_address_.end() ? 0 : at->second;
  if (held >= caps_.per_address) return {Admission::kAddressFull, false};
  const bool counted = !is_operator(address);
  if (counted && counted_ >= caps_.total) return {Admission::kServerFull, false};
  ++by_address_[address];
  if (counted) ++counted_;
  ++open_;
  return {Admission::kAdmitted, counted};
}

void ConnectionLimits::release(const std::string& address, const Ticket& ticket) {
  if (ticket.admission != Admission::kAdmitted) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto at = by_address_.find(address);
  if (at == by_address_.end()) return;
  if (--at->second == 0) by_address_.erase(at);
  if (ticket.counted) --counted_;
  --open_;
}

void ConnectionLimits::remember_operator(const std::string& address) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (is_operator(address)) return;
  operators_.push_back(address);
  while (operators_.size() > caps_.operators_remembered) operators_.pop_front();
}

std::size_t ConnectionLimits::open() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return open_;
}

}  // namespace planter::console
