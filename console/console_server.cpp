#include "console/console_server.h"

#include <httplib.h>
#include <pthread.h>
#include <sched.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "console/guarded_server.h"
#include "console/json_number.h"

namespace planter::console {

std::string console_page();      // console_page.html, embedded at build time
std::string console_dygraphs();  // Debian's libjs-dygraphs, embedded at build time

namespace {
// Requests carry no body the console needs: anything larger is refused unread.
constexpr std::size_t kMaxBodyBytes = 4096;
// What the page may load and do: only its own inline script and style, and this server.
constexpr const char* kContentSecurityPolicy =
    "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; "
    "connect-src 'self'; img-src data:; base-uri 'none'; form-action 'none'; "
    "frame-ancestors 'none'";

// Why a request's framing is refused (RFC 9112: Sec. 3.2, one Host; Sec. 6.3, a message with
// both Transfer-Encoding and Content-Length, or Content-Lengths that disagree, cannot be framed
// safely; Sec. 5.5, no control characters in a field value), or nullptr.
const char* framing_refusal(const httplib::Request& req) {
  if (req.get_header_value_count("Host") != 1) return "a request names exactly one Host";
  if (req.get_header_value_count("Content-Length") > 1) return "more than one Content-Length";
  if (req.has_header("Content-Length") && req.has_header("Transfer-Encoding"))
    return "both Content-Length and Transfer-Encoding";
  for (const auto& [name, value] : req.headers) {
    for (const char c : value) {
      const auto u = static_cast<unsigned char>(c);
      if ((u < 0x20 && u != '\t') || u == 0x7f) return "a control character in a header's value";
    }
  }
  return nullptr;
}

}  // namespace

void leave_the_loop(int loop_cpu) {
  sched_param normal{};
  normal.sched_priority = 0;
  pthread_setschedparam(pthread_self(), SCHED_OTHER, &normal);
  const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
  if (loop_cpu < 0 || cpus < 2) return;
  cpu_set_t set;
  CPU_ZERO(&set);
  for (long c = 0; c < cpus && c < CPU_SETSIZE; ++c)
    if (c != loop_cpu) CPU_SET(static_cast<int>(c), &set);
  pthread_setaffinity_np(pthread_self(), sizeof set, &set);
}

ConsoleServer::ConsoleServer(const ConsoleOptions& options, const ConsoleInfo& info)
    : options_(options),
      info_(info),
      queue_(1024),
      sessions_(
          std::make_unique<OperatorSessions>(options.secrets, options.policy, console_now_ns)),
      host_names_(options.host_names),
      limits_(ConnectionCaps{}, cut_socket) {
  if (options_.commands != nullptr &&
      OperatorSessions::normalise(options_.secrets.pairing).size() < kSecretLettersMin)
    throw std::runtime_error("console: commands need a pairing secret of at least 12 letters");
  page_ = console_page();
  const std::string marker = "/*DYGRAPHS*/";
  const auto at = page_.find(marker);
  if (at == std::string::npos) throw std::logic_error("console page has no dygraphs marker");
  page_.replace(at, marker.size(), console_dygraphs());
}

ConsoleServer::~ConsoleServer() { stop(); }

bool ConsoleServer::publish(const LiveSample& sample) {
  if (queue_.push(sample)) return true;
  dropped_.fetch_add(1, std::memory_order_relaxed);
  return false;
}

void ConsoleServer::drain() {
  LiveSample s;
  while (queue_.pop(s)) {
    history_.push_back(s);
    if (history_.size() > options_.history) history_.pop_front();
  }
}

std::string ConsoleServer::state_json() {
  std::lock_guard<std::mutex> lock(history_mutex_);
  drain();
  if (history_.empty()) return "{\"t_s\":null,\"state\":\"no data yet\"}";
  return to_json(history_.back(),
                 options_.recording != nullptr ? options_.recording->active() : std::string());
}

std::string ConsoleServer::history_json() {
  std::lock_guard<std::mutex> lock(history_mutex_);
  drain();
  // Columns, not rows: the page hands them to the charts as they are.
  nlohmann::json t = nlohmann::json::array(), v = nlohmann::json::array(),
                 sigma_seen = nlohmann::json::array(), sigma_true = nlohmann::json::array(),
                 force = nlohmann::json::array(), force_target = nlohmann::json::array(),
                 depth = nlohmann::json::array(), depth_target = nlohmann::json::array();
  for (const LiveSample& s : history_) {
    t.push_back(s.t_s);
    v.push_back(json_number(s.v_mps));
    sigma_seen.push_back(json_number(s.sigma_seen));
    sigma_true.push_back(json_number(s.sigma_true));
    force.push_back(json_number(s.clamp_force_N));
    force_target.push_back(json_number(s.clamp_force_target_N));
    depth.push_back(json_number(s.depth_mm));
    depth_target.push_back(json_number(s.depth_target_mm));
  }
  return nlohmann::json{{"t_s", t},
                        {std::string(signal_key("v_wheel")), v},
                        {std::string(signal_key("sigma")), sigma_seen},
                        {kTrueSigmaKey, sigma_true},
                        {std::string(signal_key("clamp_force")), force},
                        {std::string(signal_key("clamp_force_cmd")), force_target},
                        {std::string(signal_key("depth_mm")), depth},
                        {std::string(signal_key("depth_target_mm")), depth_target}}
      .dump();
}

void ConsoleServer::start() {
  if (options_.commands != nullptr) audit_ = std::make_unique<AuditLog>(options_.audit_log);
  server_ = std::make_unique<GuardedServer>(limits_, ConnectionTimes{});
  GuardedServer& srv = *server_;
  srv.set_payload_max_length(kMaxBodyBytes);
  // SO_REUSEADDR only: cpp-httplib's default adds SO_REUSEPORT, with which a second console
  // on the same port would start without a word and share the connections.
  srv.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  srv.set_default_headers({{"Content-Security-Policy", kContentSecurityPolicy},
                           {"X-Content-Type-Options", "nosniff"},
                           {"Referrer-Policy", "no-referrer"},
                           {"Cache-Control", "no-store"}});
  const nlohmann::json info = {
      {"title", info_.title},
      {"clamp_ceiling_N", info_.clamp_ceiling_N},
      {"target_spacing_mm", info_.target_spacing_mm},
      {"row_spacing_mm", info_.row_spacing_mm},
      {"spacing_cv_alarm", info_.spacing_cv_alarm},
      {"singulation_alarm_pct", info_.singulation_alarm_pct},
      {"disc_top_speed_mps", info_.disc_top_speed_mps},
      {"photo_eye", info_.photo_eye},
      {"simulated", info_.simulated},
      {"can_command", options_.commands != nullptr},
      {"can_record", options_.recording != nullptr && options_.commands != nullptr},
      {"recordings", !options_.recordings_dir.empty()},
      {"viewing_open", sessions_->viewing_open()},
      {"depth_min_mm", info_.depth_range_mm.min},
      {"depth_max_mm", info_.depth_range_mm.max},
      {"clamp_force_min_N", info_.clamp_force_range_N.min},
      {"clamp_force_max_N", info_.clamp_force_range_N.max},
      {"clamp_force_max_exclusive", info_.clamp_force_range_N.max_exclusive}};
  const std::string info_text = info.dump();
  srv.Get("/", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(page_, "text/html; charset=utf-8");
  });
  srv.Get("/api/info", [info_text](const httplib::Request&, httplib::Response& res) {
    res.set_content(info_text, "application/json");
  });
  srv.Get("/api/state", [this](const httplib::Request& req, httplib::Response& res) {
    if (may_view(req, res)) res.set_content(state_json(), "application/json");
  });
  srv.Get("/api/history", [this](const httplib::Request& req, httplib::Response& res) {
    if (may_view(req, res)) res.set_content(history_json(), "application/json");
  });
  // Every request names this machine in Host, or it is refused before any route (DNS
  // rebinding: another site's page that made its own name resolve here).
  // A request framed two ways is refused first (framing_refusal); either refusal closes the
  // connection (guarded_server.h).
  srv.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (const char* why = framing_refusal(req)) {
      res.status = 400;
      res.set_content(std::string("refused: ") + why + "\n", "text/plain");
      return httplib::Server::HandlerResponse::Handled;
    }
    std::lock_guard<std::mutex> lock(host_names_mutex_);
    if (host_names_.allowed(req.get_header_value("Host")))
      return httplib::Server::HandlerResponse::Unhandled;
    // Not the names it answers to: a page that rebinds a name here must learn none of them.
    res.status = 421;
    res.set_content("refused: this console is not reached by that name\n", "text/plain");
    return httplib::Server::HandlerResponse::Handled;
  });
  install_command_routes(srv);
  if (!options_.recordings_dir.empty()) install_recording_routes(srv);
  // Every other method and path is refused, said in words.
  srv.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (res.status == 404) res.set_content("no such page\n", "text/plain");
  });
  if (options_.port == 0) {
    port_ = srv.bind_to_any_port(options_.bind);
  } else {
    port_ = srv.bind_to_port(options_.bind, options_.port) ? options_.port : -1;
  }
  if (port_ > 0) server_->widen_backlog();
  if (port_ <= 0)
    throw std::runtime_error("console: cannot listen on " + options_.bind + ":" +
                             std::to_string(options_.port) +
                             " (in use, or not an address of this machine; --port, --bind)");
  thread_ = std::thread([&srv, cpu = options_.loop_cpu] {
    leave_the_loop(cpu);
    srv.listen_after_bind();
  });
  drainer_ = std::thread([this] {
    leave_the_loop(options_.loop_cpu);
    std::unique_lock<std::mutex> lock(drainer_mutex_);
    while (!drainer_wake_.wait_for(lock, std::chrono::milliseconds(200),
                                   [this] { return drainer_stop_; })) {
      const std::lock_guard<std::mutex> history_lock(history_mutex_);
      drain();
    }
  });
}

void ConsoleServer::stop() {
  if (server_) server_->stop();
  if (thread_.joinable()) thread_.join();
  {
    const std::lock_guard<std::mutex> lock(drainer_mutex_);
    drainer_stop_ = true;
  }
  drainer_wake_.notify_all();
  if (drainer_.joinable()) drainer_.join();
  // The refused logins not yet said are said before the log closes.
  audit_refusals(refused_logins_.take(console_now_ns()));
}

}  // namespace planter::console
