// The console's routes that change something or open a session: login, logout, commands, and
// the recordings' downloads. What a security reviewer checks is all here, in order:
// origin, content type, session, CSRF token, role, audit log, body, rate, then the loop.
#include <httplib.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <regex>

#include "console/client_address.h"
#include "console/console_request.h"
#include "console/console_server.h"

namespace planter::console {
namespace {
constexpr const char* kCookie = "planter_session";
constexpr auto kAnswerTimeout = std::chrono::milliseconds(1000);

void answer(httplib::Response& res, int status, const nlohmann::json& body) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
}
void error(httplib::Response& res, int status, const std::string& words) {
  answer(res, status, {{"error", words}});
}

std::string cookie_token(const httplib::Request& req) {
  return session_cookie(req.get_header_value("Cookie"));
}

// A request that changes something must come from this console's own page: a browser names
// the page's origin, and it must be this server's; a cross-site fetch is refused before any
// secret or session is looked at. Clients that are not browsers send no Origin: the CSRF
// token still binds them to a session.
// Returns the refusal's words (also answered in res), or "" when the request may go on.
std::string refused_origin(const httplib::Request& req, httplib::Response& res) {
  const std::string origin = req.get_header_value("Origin");
  const std::string site = req.get_header_value("Sec-Fetch-Site");
  std::string words;
  int status = 403;
  if ((!origin.empty() && origin != "http://" + req.get_header_value("Host")) ||
      (!site.empty() && site != "same-origin" && site != "none")) {
    words =
        "refused: the request came from another site (" + (origin.empty() ? site : origin) + ")";
  } else if (req.get_header_value("Content-Type").rfind("application/json", 0) != 0) {
    // A JSON body cannot be sent across sites without the browser asking first.
    words = "send the command as application/json";
    status = 415;
  }
  if (!words.empty()) error(res, status, words);
  return words;
}

std::string range_text(const SetpointRange& r, const char* unit) {
  return number_text(r.min) + " to " + (r.max_exclusive ? "below " : "") + number_text(r.max) +
         " " + unit;
}

int http_status(ConsoleResult r) {
  switch (r) {
    case ConsoleResult::kAccepted:
      return 200;
    case ConsoleResult::kOutOfRange:
      return 422;
    case ConsoleResult::kRefused:
      return 409;
    case ConsoleResult::kFailed:
      return 500;
    case ConsoleResult::kNoAnswer:
      return 504;
  }
  return 500;
}
}  // namespace

bool ConsoleServer::may_view(const httplib::Request& req, httplib::Response& res) {
  if (sessions_->viewing_open() || sessions_->find(cookie_token(req))) return true;
  error(res, 401, "log in with the viewer secret to see this machine");
  return false;
}

bool ConsoleServer::audit(const std::string& address, const std::string& session,
                          const std::string& what, const std::string& value,
                          const std::string& result) {
  if (!audit_) return true;
  audit_refusals(refused_logins_.take(console_now_ns()));
  return audit_->append(address, session, what, value, result);
}

void ConsoleServer::audit_refusals(const std::optional<RefusalSummary>& s) {
  if (s && audit_) audit_->append(s->address, "-", s->what, s->value, s->words);
}

void ConsoleServer::login(const httplib::Request& req, httplib::Response& res) {
  const auto secret = login_secret(req.body);
  if (!secret) return error(res, 400, "send {\"secret\": \"...\"}");
  const std::string client = client_key(req.remote_addr);  // a /64 for IPv6 (client_address.h)
  const LoginResult r = sessions_->login(client, *secret);
  if (r.status == LoginResult::Status::kOk) {
    // The operator's device keeps a way in however many others hold connections.
    if (r.role == Role::kOperator) limits_.remember_operator(client);
    res.set_header("Set-Cookie",
                   std::string(kCookie) + "=" + r.token + "; HttpOnly; SameSite=Strict; Path=/");
    nlohmann::json body = {{"role", role_name(r.role)}, {"csrf", r.csrf}};
    // Logged in even without an audit log: the operator may need to stop the machine.
    if (!audit(req.remote_addr, r.id, "login", "-",
               std::string("logged in as ") + role_name(r.role)))
      body["warning"] =
          "the audit log " + audit_->path() + " cannot be written: only stop is taken";
    return answer(res, 200, body);
  }
  std::string said;
  if (r.status == LoginResult::Status::kWrongSecret) {
    said = "wrong secret";
    error(res, 401, "wrong secret (the pairing secret is on the machine's label)");
  } else {
    const long wait = std::lround(r.retry_after_s);
    res.set_header("Retry-After", std::to_string(wait));
    said = std::string(r.status == LoginResult::Status::kRateLimited
                           ? "too many wrong secrets"
                           : "too many logins from this address") +
           ": wait " + std::to_string(wait) + " s";
    error(res, 429, said);
  }
  // Counted, and said once a minute: a flood of wrong secrets cannot fill the disk.
  audit_refusals(refused_logins_.add(client, said, console_now_ns()));
}

void ConsoleServer::command(const httplib::Request& req, httplib::Response& res) {
  const std::string token = cookie_token(req);
  const auto session = sessions_->find(token);
  const std::string who = session ? session->id : "-";
  const CommandBody body = parse_command_body(req.body);
  const std::string& what = body.name;
  const std::string& value = body.value_text;
  // Every answer below is also written to the audit log.
  const auto refuse = [&](int status, const std::string& words) {
    error(res, status, words);
    audit(req.remote_addr, who, what, value, words);
  };
  if (!session) return refuse(401, "log in with the pairing secret to give commands");
  if (req.get_header_value("X-CSRF-Token") != session->csrf)
    return refuse(403, "refused: the request has no valid CSRF token (reload the page)");
  if (session->role != Role::kOperator)
    return refuse(403, "refused: a viewer cannot give commands; log in with the pairing secret");
  if (!body.ok) return refuse(400, body.error);
  const ConsoleCommandKind kind = body.kind;
  // Without an audit log no command is given, but stop: safety first.
  const bool stopping = kind == ConsoleCommandKind::kStop;
  if (!audit_->ok() && !stopping) {
    error(res, 503,
          "refused: the audit log " + audit_->path() + " cannot be written (stop is still taken)");
    return;
  }
  const bool recording =
      kind == ConsoleCommandKind::kRecordStart || kind == ConsoleCommandKind::kRecordStop;
  if (recording && options_.recording == nullptr)
    return refuse(409, "refused: this machine does not record from the console");
  if (!sessions_->take_command(token))
    return refuse(429, "too many commands: at most " +
                           std::to_string(options_.policy.commands_per_window) + " in " +
                           number_text(options_.policy.command_window_s) + " s");
  // Recordings are the program's, not the loop's: answered here, in the server's thread.
  const ConsoleReply reply =
      !recording ? options_.commands->submit(kind, body.value, kAnswerTimeout)
      : kind == ConsoleCommandKind::kRecordStart ? options_.recording->start()
                                                 : options_.recording->stop();
  std::string words = reply.text;
  if (reply.result == ConsoleResult::kOutOfRange)
    words = what + " " + value + " is outside " +
            (kind == ConsoleCommandKind::kSetDepth ? range_text(info_.depth_range_mm, "mm")
                                                   : range_text(info_.clamp_force_range_N, "N")) +
            ": nothing changed";
  const int status = http_status(reply.result);
  if (!audit(req.remote_addr, who, what, value, words))
    words +=
        " (the audit log " + audit_->path() + " cannot be written: only stop is taken from now)";
  answer(res, status,
         {{"result", status == 200 ? "accepted" : "refused"},
          {"message", words},
          {"t_s", recording ? nlohmann::json(nullptr) : nlohmann::json(reply.t_s)}});
}

void ConsoleServer::install_command_routes(httplib::Server& srv) {
  srv.Get("/api/session", [this](const httplib::Request& req, httplib::Response& res) {
    const auto s = sessions_->find(cookie_token(req));
    if (!s) return error(res, 401, "no session");
    answer(res, 200, {{"role", role_name(s->role)}, {"csrf", s->csrf}});
  });
  srv.Post("/api/login", [this](const httplib::Request& req, httplib::Response& res) {
    if (refused_origin(req, res).empty()) login(req, res);
  });
  srv.Post("/api/logout", [this](const httplib::Request& req, httplib::Response& res) {
    if (!refused_origin(req, res).empty()) return;
    sessions_->logout(cookie_token(req));
    res.set_header("Set-Cookie", std::string(kCookie) + "=; Max-Age=0; Path=/");
    answer(res, 200, {{"role", "none"}});
  });
  if (options_.commands == nullptr) return;
  srv.Post("/api/command", [this](const httplib::Request& req, httplib::Response& res) {
    const std::string refused = refused_origin(req, res);
    if (refused.empty()) return command(req, res);
    audit(req.remote_addr, "-", "command", "-", refused);
  });
}

void ConsoleServer::install_recording_routes(httplib::Server& srv) {
  namespace fs = std::filesystem;
  // Only names the console itself gives: no path, no dot first.
  static const std::regex kName("[A-Za-z0-9][A-Za-z0-9._-]*\\.csv");
  srv.Get("/api/recordings", [this](const httplib::Request& req, httplib::Response& res) {
    if (!may_view(req, res)) return;
    nlohmann::json list = nlohmann::json::array();
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(options_.recordings_dir, ec)) {
      const std::string name = e.path().filename().string();
      if (e.is_regular_file(ec) && std::regex_match(name, kName))
        list.push_back({{"name", name}, {"bytes", e.file_size(ec)}});
    }
    std::sort(list.begin(), list.end(),
              [](const auto& a, const auto& b) { return a["name"] < b["name"]; });
    answer(res, 200, {{"recordings", list}});
  });
  srv.Get(R"(/api/recordings/([A-Za-z0-9][A-Za-z0-9._-]*\.csv))",
          [this](const httplib::Request& req, httplib::Response& res) {
            if (!may_view(req, res)) return;
            const std::string name = req.matches[1];
            const fs::path path = fs::path(options_.recordings_dir) / name;
            auto file = std::make_shared<std::ifstream>(path, std::ios::binary);
            std::error_code ec;
            const auto size = fs::file_size(path, ec);
            if (!*file || ec) return error(res, 404, "no recording " + name);
            // A 32-bit board's server counts bytes in 32 bits: a larger file is said, not cut.
            if (size > std::numeric_limits<std::size_t>::max())
              return error(res, 413,
                           "recording " + name + " is too large to download from this board (" +
                               std::to_string(size) + " bytes); copy it from the machine");
            res.set_header("Content-Disposition", "attachment; filename=\"" + name + "\"");
            // The size when asked: a recording still being written is sent as far as it was.
            res.set_content_provider(
                static_cast<std::size_t>(size), "text/csv",
                [file](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                  char buffer[65536];
                  file->seekg(static_cast<std::streamoff>(offset));
                  file->read(buffer, static_cast<std::streamsize>(
                                         std::min<std::size_t>(length, sizeof buffer)));
                  const auto got = file->gcount();
                  if (got <= 0) return false;
                  return sink.write(buffer, static_cast<std::size_t>(got));
                });
          });
}

}  // namespace planter::console
