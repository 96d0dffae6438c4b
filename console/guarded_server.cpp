#include "console/guarded_server.h"

#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "console/client_address.h"

namespace planter::console {
namespace {

using Clock = std::chrono::steady_clock;
// How often a wait looks whether the server is stopping.
constexpr std::chrono::milliseconds kStopCheck{100};

// One end of a connection as numbers: the peer's (getpeername) or ours (getsockname).
Endpoint endpoint_of(socket_t sock, bool peer) {
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  const int got = peer ? getpeername(sock, reinterpret_cast<sockaddr*>(&addr), &len)
                       : getsockname(sock, reinterpret_cast<sockaddr*>(&addr), &len);
  Endpoint e;
  char host[NI_MAXHOST];
  if (got != 0 || getnameinfo(reinterpret_cast<sockaddr*>(&addr), len, host, sizeof host, nullptr,
                              0, NI_NUMERICHOST) != 0)
    return e;
  e.ip = host;
  if (addr.ss_family == AF_INET) e.port = ntohs(reinterpret_cast<sockaddr_in*>(&addr)->sin_port);
  if (addr.ss_family == AF_INET6) e.port = ntohs(reinterpret_cast<sockaddr_in6*>(&addr)->sin6_port);
  return e;
}

// A whole answer in one send that never waits: for a client refused before it was read. Built
// by appending (GCC 12's -Wrestrict misreads "literal" + std::string on armhf).
void refuse(socket_t sock, int status, const char* reason, const std::string& words) {
  std::string answer = "HTTP/1.1 ";
  answer.append(std::to_string(status)).append(" ").append(reason);
  answer.append("\r\nContent-Type: text/plain\r\nContent-Length: ");
  answer.append(std::to_string(words.size()));
  answer.append("\r\nRetry-After: 5\r\nConnection: close\r\n\r\n").append(words);
  (void)!send(sock, answer.data(), answer.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
}

// "refused: " followed by the parts, appended (see refuse()).
std::string refusal(std::initializer_list<std::string_view> parts) {
  std::string words = "refused: ";
  for (std::string_view p : parts) words.append(p);
  return words.append("\n");
}

// The connection as cpp-httplib reads and writes it, with a byte budget and deadlines.
class BoundedStream final : public httplib::Stream {
 public:
  // `peer`: the client's end, read once when the connection was admitted.
  BoundedStream(socket_t sock, Endpoint peer, const std::atomic<socket_t>& listening,
                const ConnectionTimes& t)
      : sock_(sock), peer_(std::move(peer)), listening_(listening), times_(t) {}

  // Each request gets the whole budget and its own deadlines.
  void next_request() {
    consumed_ = 0;
    cut_ = Cut::kNone;
    in_head_ = first_line_ = true;
    colon_ = false;
    line_length_ = 0;
    answer_started_ = replacing_ = false;
    status_ = 0;
    read_deadline_ = Clock::now() + times_.request_read;
    write_deadline_.reset();
  }
  // Waits for the next request's first byte, at most the idle time.
  bool next_request_arrives() {
    if (have_ > used_) return true;
    return wait(POLLIN, Clock::now() + times_.idle);
  }
  // The request could not be read whole (too large, too slow, or the client went): the
  // connection ends after the answer.
  [[nodiscard]] bool cut() const { return cut_ != Cut::kNone; }
  // The answer refused the request (4xx, 5xx): the connection ends after it, as what follows on
  // the wire may be the refused request's unread body or a request smuggled behind it (RFC 9112,
  // Sec. 11.2; after a framing error the server cannot know where the next request starts).
  [[nodiscard]] bool refused() const { return status_ >= 400; }

  bool is_readable() const override { return have_ > used_ || wait(POLLIN, read_deadline_); }
  bool is_writable() const override { return wait(POLLOUT, write_deadline()); }

  ssize_t read(char* ptr, size_t size) override {
    if (consumed_ >= times_.request_bytes) {
      cut_ = Cut::kTooLarge;
      return -1;
    }
    size = std::min(size, times_.request_bytes - consumed_);
    if (have_ == used_) {
      if (!wait(POLLIN, read_deadline_)) {
        cut_ = Cut::kTooSlow;
        return -1;
      }
      ssize_t n;
      do {
        n = recv(sock_, buffer_, sizeof buffer_, 0);
      } while (n < 0 && errno == EINTR);
      if (n <= 0) {
        cut_ = Cut::kGone;
        return n;
      }
      have_ = static_cast<std::size_t>(n);
      used_ = 0;
    }
    const std::size_t n = std::min(size, have_ - used_);
    if (!head_lines_well_formed(buffer_ + used_, n)) {
      cut_ = Cut::kMalformed;
      return -1;
    }
    std::memcpy(ptr, buffer_ + used_, n);
    used_ += n;
    consumed_ += n;
    return static_cast<ssize_t>(n);
  }

  ssize_t write(const char* ptr, size_t size) override {
    if (!answer_started_) {
      answer_started_ = true;
      status_ = status_code(std::string_view(ptr, size));
      // cpp-httplib answers a request it could not read with a bare 400; this one says why.
      // Its other answers (413 for a declared body too large, say) go out as they are.
      static constexpr std::string_view kBare400 = "HTTP/1.1 400 ";
      replacing_ = (cut_ == Cut::kTooLarge || cut_ == Cut::kTooSlow || cut_ == Cut::kMalformed) &&
                   std::string_view(ptr, size).substr(0, kBare400.size()) == kBare400;
      if (replacing_ && cut_ == Cut::kMalformed)
        refuse(sock_, 400, "Bad Request",
               refusal({"a header line without a colon (RFC 9112, Sec. 5)"}));
      else if (replacing_ && cut_ == Cut::kTooLarge)
        refuse(sock_, 431, "Request Header Fields Too Large",
               refusal({"a request of more than ", std::to_string(times_.request_bytes),
                        " bytes (request line, headers and body)"}));
      else if (replacing_)
        refuse(sock_, 408, "Request Timeout",
               refusal({"the request did not arrive whole within ",
                        std::to_string(times_.request_read.count() / 1000), " s"}));
    }
    if (replacing_) return static_cast<ssize_t>(size);
    if (!write_deadline_) write_deadline_ = Clock::now() + times_.response_write;
    if (!wait(POLLOUT, *write_deadline_)) return -1;
    ssize_t n;
    do {
      n = send(sock_, ptr, size, MSG_NOSIGNAL);
    } while (n < 0 && errno == EINTR);
    return n;
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    ip = peer_.ip;
    port = peer_.port;
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    Endpoint ours = endpoint_of(sock_, false);
    ip = std::move(ours.ip);
    port = ours.port;
  }
  socket_t socket() const override { return sock_; }

 private:
  [[nodiscard]] Clock::time_point write_deadline() const {
    return write_deadline_ ? *write_deadline_ : Clock::now() + times_.response_write;
  }
  // The request's head, line by line as its bytes are handed out: every line after the request
  // line must be a field with a colon (RFC 9112, Sec. 5). cpp-httplib skips one without, which a
  // proxy in front may read otherwise; it is refused here. Empty lines before the request line
  // are allowed (Sec. 2.2); the body after the empty line is not looked at.
  bool head_lines_well_formed(const char* bytes, std::size_t n) {
    for (std::size_t i = 0; i < n && in_head_; ++i) {
      const char c = bytes[i];
      if (c == '\n') {
        if (line_length_ == 0 && !first_line_) in_head_ = false;
        if (line_length_ > 0 && !first_line_ && !colon_) return false;
        if (line_length_ > 0) first_line_ = false;
        colon_ = false;
        line_length_ = 0;
      } else if (c != '\r') {
        ++line_length_;
        colon_ = colon_ || c == ':';
      }
    }
    return true;
  }
  // Until the socket is ready, the deadline passes or the server stops.
  bool wait(short events, Clock::time_point deadline) const {
    for (;;) {
      if (listening_.load() == INVALID_SOCKET) return false;
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) return false;
      pollfd p{sock_, events, 0};
      const int n = poll(&p, 1, static_cast<int>(std::min(left, kStopCheck).count()));
      if (n > 0) return true;
      if (n < 0 && errno != EINTR) return false;
    }
  }

  socket_t sock_;
  Endpoint peer_;
  const std::atomic<socket_t>& listening_;
  const ConnectionTimes& times_;
  char buffer_[4096];
  std::size_t have_ = 0, used_ = 0;
  std::size_t consumed_ = 0;
  enum class Cut { kNone, kTooLarge, kTooSlow, kGone, kMalformed } cut_ = Cut::kNone;
  bool in_head_ = true, first_line_ = true, colon_ = false;  // head_lines_well_formed()
  std::size_t line_length_ = 0;
  bool answer_started_ = false, replacing_ = false;
  int status_ = 0;  // of this request's answer, from its status line

  static int status_code(std::string_view line) {
    static constexpr std::string_view kVersion = "HTTP/1.1 ";
    if (line.size() < kVersion.size() + 3 || line.substr(0, kVersion.size()) != kVersion) return 0;
    int code = 0;
    for (char c : line.substr(kVersion.size(), 3)) {
      if (c < '0' || c > '9') return 0;
      code = code * 10 + (c - '0');
    }
    return code;
  }
  Clock::time_point read_deadline_{};
  std::optional<Clock::time_point> write_deadline_;
};

}  // namespace

void cut_socket(int sock) { ::shutdown(sock, SHUT_RDWR); }

GuardedServer::GuardedServer(ConnectionLimits& limits, ConnectionTimes times)
    : limits_(limits), times_(times) {
  // More workers than connections can be admitted, so a refusal is never queued behind them.
  const ConnectionCaps& caps = limits_.caps();
  const std::size_t workers = caps.total + caps.operators_remembered * caps.per_address + 8;
  new_task_queue = [workers] { return new httplib::ThreadPool(workers); };
}

void GuardedServer::widen_backlog() {
  const socket_t sock = svr_sock_.load();
  if (sock != INVALID_SOCKET) ::listen(sock, SOMAXCONN);
}

bool GuardedServer::process_and_close_socket(socket_t sock) {
  Endpoint peer = endpoint_of(sock, true);
  const std::string address = client_key(peer.ip);  // a /64 for IPv6 (client_address.h)
  const Ticket ticket = limits_.admit(address, sock);
  bool served = false;
  if (ticket.admission == Admission::kAddressFull) {
    refuse(sock, 429, "Too Many Requests",
           refusal({std::to_string(limits_.caps().per_address),
                    " connections from this address are open already"}));
  } else if (ticket.admission == Admission::kServerFull) {
    refuse(sock, 503, "Service Unavailable", refusal({"the console is busy; try again"}));
  } else {
    served = serve(sock, std::move(peer), ticket);
  }
  limits_.release(address, ticket);
  shutdown(sock, SHUT_RDWR);
  close(sock);
  return served;
}

bool GuardedServer::serve(socket_t sock, Endpoint peer, const Ticket& ticket) {
  BoundedStream stream(sock, std::move(peer), svr_sock_, times_);
  bool ok = false;
  for (std::size_t n = 0; n < times_.requests_per_connection; ++n) {
    // While it waits, its slot may go to a newcomer (connection_limits.h): then it ends.
    if (!limits_.set_idle(ticket, true)) break;
    const bool arrived = stream.next_request_arrives();
    if (!limits_.set_idle(ticket, false) || !arrived) break;
    stream.next_request();
    bool closed = false;
    ok = process_request(stream, n + 1 == times_.requests_per_connection, closed, nullptr);
    if (!ok || closed || stream.cut() || stream.refused()) break;
  }
  return ok;
}

}  // namespace planter::console
