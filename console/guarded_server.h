#pragma once
// cpp-httplib's server with the connection handling replaced by one that holds on the farm's
// network (issue 28, items 1-2). cpp-httplib parses the requests and routes them; what it lacks
// is bounded here:
// - admission before a byte is read: ConnectionLimits' caps per address and in all, a refused
//   connection answered 503 at once and closed, on a worker kept free for it; a full server
//   makes room for an address with fewer connections by cutting another's idle one;
// - every request read within a deadline from its first byte (a slow sender is cut), an idle
//   keep-alive connection closed after a few seconds, every response written within a deadline;
// - at most a fixed number of bytes read for one request, headers and body together, however
//   many header lines are sent: past that the request is answered 431 and the connection closed,
//   so memory stays bounded whatever arrives;
// - a fixed pool of workers (cpp-httplib's ThreadPool, sized here) larger than the connections
//   admitted, so a refusal never waits behind a slow connection.
#include <httplib.h>

#include <chrono>
#include <cstddef>
#include <string>

#include "console/connection_limits.h"

namespace planter::console {

struct ConnectionTimes {
  std::chrono::milliseconds request_read{10000};  // first byte to the end of the body
  std::chrono::milliseconds idle{5000};           // between requests on one connection
  std::chrono::milliseconds response_write{10000};
  std::size_t request_bytes = 64 * 1024;  // request line, headers and body
  std::size_t requests_per_connection = 50;
};

// One end of a connection as numbers.
struct Endpoint {
  std::string ip;
  int port = 0;
};

// Ends a connection from another thread: its worker's wait wakes, and it closes the socket.
void cut_socket(int sock);

class GuardedServer : public httplib::Server {
 public:
  GuardedServer(ConnectionLimits& limits, ConnectionTimes times);
  // After binding: the kernel's queue of connections not yet accepted as long as it allows
  // (cpp-httplib asks for 5, which a burst of refused connections fills).
  void widen_backlog();
  // What a worker does with an accepted connection, on the calling thread: admits it, serves
  // it within the bounds, closes it (the fuzz target feeds it one, tests/fuzz).
  bool serve_connection(socket_t sock) { return process_and_close_socket(sock); }

 private:
  bool process_and_close_socket(socket_t sock) override;
  bool serve(socket_t sock, Endpoint peer, const Ticket& ticket);

  ConnectionLimits& limits_;
  ConnectionTimes times_;
};

}  // namespace planter::console
