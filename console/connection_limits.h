#pragma once
// Who may hold one of the console's connections (issue 28, items 1-2): at most a few at once
// from one address, and a total across all addresses, so no number of idle or slow connections
// from the farm's network fills the server. An address that has logged in as the operator is
// reserved a way past the total (its own share still capped), so a crowd of other addresses
// cannot keep the operator from Stop. Plain counting, no I/O: the server asks before it reads a
// byte of a connection and says when the connection is gone.
#include <cstddef>
#include <deque>
#include <map>
#include <mutex>
#include <string>

namespace planter::console {

struct ConnectionCaps {
  std::size_t per_address = 8;  // a browser opens up to 6 to one host
  std::size_t total = 32;       // all addresses together, the operator's aside
  std::size_t operators_remembered = 8;
};

enum class Admission { kAdmitted, kAddressFull, kServerFull };
struct Ticket {
  Admission admission = Admission::kServerFull;
  bool counted = false;  // against the total (false: the operator's reserved way)
};

class ConnectionLimits {
 public:
  explicit ConnectionLimits(ConnectionCaps caps) : caps_(caps) {}

  // Whether a connection from this address may be served; an admitted one is counted until
  // release() is given its ticket.
  Ticket admit(const std::string& address);
  void release(const std::string& address, const Ticket& ticket);
  // The address logged in as the operator: from now its connections pass the total.
  void remember_operator(const std::string& address);

  [[nodiscard]] std::size_t open() const;
  [[nodiscard]] const ConnectionCaps& caps() const { return caps_; }

 private:
  [[nodiscard]] bool is_operator(const std::string& address) const;

  ConnectionCaps caps_;
  mutable std::mutex mutex_;
  std::map<std::string, std::size_t> by_address_;  // only addresses holding a connection
  std::size_t counted_ = 0;                        // against the total
  std::size_t open_ = 0;
  std::deque<std::string> operators_;  // newest last, at most operators_remembered
};

}  // namespace planter::console
