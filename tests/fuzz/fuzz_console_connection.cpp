// Fuzz target: the bytes of one connection to the console, as the bounded server reads them
// (console/guarded_server.h) and cpp-httplib parses them: any number of requests, header lines,
// bodies and garbage, the connection closed after the last byte. Whatever arrives, what the
// server sends back starts with an HTTP/1.1 status line, and nothing crashes, overruns (ASan),
// hangs (libFuzzer's -timeout) or leaks. The seeds include a request past the budget (431).
#include <sys/socket.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "console/guarded_server.h"

namespace {

using planter::console::ConnectionCaps;
using planter::console::ConnectionLimits;
using planter::console::ConnectionTimes;
using planter::console::GuardedServer;

// Deadlines short enough for a fuzzer: every input is whole before it is served.
ConnectionTimes fuzz_times() {
  ConnectionTimes t;
  t.request_read = std::chrono::milliseconds(50);
  t.idle = std::chrono::milliseconds(50);
  t.response_write = std::chrono::milliseconds(200);
  t.request_bytes = 4096;
  return t;
}

GuardedServer& server() {
  static ConnectionLimits limits{ConnectionCaps{}};
  static GuardedServer* s = [] {
    auto* srv = new GuardedServer(limits, fuzz_times());
    srv->Get("/", [](const httplib::Request&, httplib::Response& res) {
      res.set_content("page", "text/plain");
    });
    srv->Post("/api/login", [](const httplib::Request& req, httplib::Response& res) {
      res.set_content(req.body, "application/json");
    });
    srv->set_payload_max_length(4096);
    // Bound (not listening): a server that is not stopping, as when it serves.
    if (srv->bind_to_any_port("127.0.0.1") <= 0) __builtin_trap();
    return srv;
  }();
  return *s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 64 * 1024) return 0;  // beyond the socket pair's buffer: the writer would wait
  int fds[2];
  if (socketpair(AF_UNIX, SOCK_STREAM, 0, fds) != 0) __builtin_trap();
  int big = 1 << 20;
  setsockopt(fds[1], SOL_SOCKET, SO_SNDBUF, &big, sizeof big);
  setsockopt(fds[0], SOL_SOCKET, SO_SNDBUF, &big, sizeof big);
  std::size_t sent = 0;
  while (sent < size) {
    const ssize_t n = send(fds[1], data + sent, size - sent, MSG_NOSIGNAL);
    if (n <= 0) __builtin_trap();
    sent += static_cast<std::size_t>(n);
  }
  shutdown(fds[1], SHUT_WR);
  server().serve_connection(fds[0]);  // closes fds[0]
  std::string answers;
  char buf[4096];
  for (ssize_t n; (n = recv(fds[1], buf, sizeof buf, 0)) > 0;)
    answers.append(buf, static_cast<std::size_t>(n));
  close(fds[1]);
  if (!answers.empty() && answers.rfind("HTTP/1.1 ", 0) != 0) __builtin_trap();
  return 0;
}
