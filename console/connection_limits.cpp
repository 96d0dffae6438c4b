#include "console/connection_limits.h"

#include <algorithm>

namespace planter::console {

bool ConnectionLimits::is_operator(const std::string& address) const {
  return std::find(operators_.begin(), operators_.end(), address) != operators_.end();
}

std::size_t ConnectionLimits::held(const std::string& address) const {
  const auto at = by_address_.find(address);
  return at == by_address_.end() ? 0 : at->second;
}

void ConnectionLimits::uncount(const Connection& c) {
  const auto at = by_address_.find(c.address);
  if (at != by_address_.end() && --at->second == 0) by_address_.erase(at);
  if (c.counted) --counted_;
  --open_;
}

// The oldest idle connection of the address holding the most, when that is more than the
// newcomer's address would hold with it: cut, and its slot freed now.
bool ConnectionLimits::make_room_for(const std::string& address) {
  Connection* victim = nullptr;
  std::size_t most = held(address) + 1;
  for (auto& [id, c] : connections_) {
    if (!c.counted || !c.idle || c.cut) continue;
    const std::size_t h = held(c.address);
    if (h > most) most = h, victim = &c;
  }
  if (victim == nullptr) return false;
  victim->cut = true;
  uncount(*victim);
  if (cut_ && victim->sock >= 0) cut_(victim->sock);
  return true;
}

Ticket ConnectionLimits::admit(const std::string& address, int sock) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (held(address) >= caps_.per_address) return {Admission::kAddressFull, false};
  const bool counted = !is_operator(address);
  if (counted && counted_ >= caps_.total && !make_room_for(address))
    return {Admission::kServerFull, false};
  ++by_address_[address];
  if (counted) ++counted_;
  ++open_;
  const std::uint64_t id = next_id_++;
  connections_[id] = Connection{address, sock, counted};
  return {Admission::kAdmitted, counted, id};
}

bool ConnectionLimits::set_idle(const Ticket& ticket, bool idle) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto at = connections_.find(ticket.id);
  if (at == connections_.end() || at->second.cut) return false;
  at->second.idle = idle;
  return true;
}

void ConnectionLimits::release(const std::string& address, const Ticket& ticket) {
  if (ticket.admission != Admission::kAdmitted) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto at = connections_.find(ticket.id);
  if (at == connections_.end() || at->second.address != address) return;
  if (!at->second.cut) uncount(at->second);  // a cut one was uncounted when its slot was taken
  connections_.erase(at);
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
