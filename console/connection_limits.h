#pragma once
// Who may hold one of the console's connections (issue 28, items 1-2): at most a few at once
// from one address, and a total across all addresses, so no number of idle or slow connections
// from the farm's network fills the server. An address that has logged in as the operator is
// reserved a way past the total (its own share still capped), so a crowd of other addresses
// cannot keep the operator from Stop. Before the operator's first login that reserve is not
// theirs yet (issue 53, item 2): when the total is full, a connection from an address holding
// fewer than the most takes the slot of that address's oldest idle connection (one waiting for
// a request), which is cut. Idle crowds share the total evenly, and a newcomer (the operator's
// first login, a viewer) gets in at once. Counting, and the cut through a callback: the server
// asks before it reads a byte of a connection and says when it waits and when it is gone.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
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
  std::uint64_t id = 0;  // the connection's, in the order admitted
};

class ConnectionLimits {
 public:
  // `cut` ends an idle connection's socket to make room (shutdown, so its worker wakes and
  // closes it); it is called with the limits locked, while that socket is still open.
  explicit ConnectionLimits(ConnectionCaps caps, std::function<void(int)> cut = {})
      : caps_(caps), cut_(std::move(cut)) {}

  // Whether a connection from this address may be served; an admitted one is counted until
  // release() is given its ticket. `sock` is what `cut` is given if its slot is taken.
  Ticket admit(const std::string& address, int sock = -1);
  // The connection waits for a request (idle: its slot may be taken) or reads one. False: its
  // slot was taken, and the connection must end.
  bool set_idle(const Ticket& ticket, bool idle);
  void release(const std::string& address, const Ticket& ticket);
  // The address logged in as the operator: from now its connections pass the total.
  void remember_operator(const std::string& address);

  [[nodiscard]] std::size_t open() const;
  [[nodiscard]] const ConnectionCaps& caps() const { return caps_; }

 private:
  struct Connection {
    std::string address;
    int sock = -1;
    bool counted = false, idle = false, cut = false;
  };
  [[nodiscard]] bool is_operator(const std::string& address) const;
  [[nodiscard]] std::size_t held(const std::string& address) const;
  bool make_room_for(const std::string& address);
  void uncount(const Connection& c);

  ConnectionCaps caps_;
  std::function<void(int)> cut_;
  mutable std::mutex mutex_;
  std::map<std::string, std::size_t> by_address_;    // only addresses holding a connection
  std::map<std::uint64_t, Connection> connections_;  // by id: oldest first
  std::uint64_t next_id_ = 1;
  std::size_t counted_ = 0;  // against the total
  std::size_t open_ = 0;
  std::deque<std::string> operators_;  // newest last, at most operators_remembered
};

}  // namespace planter::console
