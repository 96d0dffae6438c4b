#pragma once
// Who may do what on the console. Viewing is open, or needs the viewer secret when the board
// sets one; commands need an operator session, opened with the machine's pairing secret (made
// at installation, shown on the machine: never a default). A session is a random token in an
// HttpOnly, SameSite=Strict cookie, with its own CSRF token that every command must carry. It
// ends after `idle_s` without use and `max_s` after login. Failed logins are limited per
// address, and a limited address is refused even the right secret until its window has passed,
// so guessing gains nothing by going on. Past the limit on failures from all addresses, a wrong
// secret is refused as rate-limited, but the right one still opens a session: a flood from
// other addresses cannot lock the operator out (issue 28, item 3). Successful logins are limited
// per address too, and operators and viewers have their own session slots, so viewer logins
// never end an operator's session (item 5). Commands are limited per session.
// Time comes from the clock given, so the rules can be tested without waiting.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace planter::console {

enum class Role : std::uint8_t { kNone, kViewer, kOperator };
// The shortest secret the console takes, dashes and spaces aside.
constexpr std::size_t kSecretLettersMin = 12;
const char* role_name(Role role);

struct SessionPolicy {
  double idle_s = 15 * 60;            // an operator's phone left on the bench
  double max_s = 12 * 3600;           // one working day
  int failed_logins_per_address = 5;  // in each window
  int failed_logins_total = 20;       // from all addresses, in each window
  // Successful, in each window: an operator who logs in and stops every 5 s stays under it.
  int logins_per_address = 20;
  double login_window_s = 60;
  int commands_per_window = 10;  // per session
  double command_window_s = 10;
};

struct Secrets {
  std::string pairing;  // required for commands; empty: no one may command
  std::string viewer;   // empty: viewing is open
};

struct LoginResult {
  enum class Status : std::uint8_t {
    kOk,
    kWrongSecret,
    kRateLimited,
    kTooManyLogins
  } status = Status::kWrongSecret;
  Role role = Role::kNone;
  std::string token;  // the session cookie's value
  std::string csrf;   // to send back in X-CSRF-Token
  std::string id;     // the session's name in the audit log (not part of the token)
  double retry_after_s = 0;
};

struct SessionView {
  Role role = Role::kNone;
  std::string id;  // a short, non-secret name of the session for the audit log
  std::string csrf;
};

class OperatorSessions {
 public:
  using Clock = std::function<std::int64_t()>;  // monotonic nanoseconds
  OperatorSessions(Secrets secrets, SessionPolicy policy, Clock now_ns);

  [[nodiscard]] bool viewing_open() const { return secrets_.viewer.empty(); }
  LoginResult login(const std::string& address, const std::string& secret);
  // The live session behind a cookie token (its last use is now), or nothing.
  std::optional<SessionView> find(const std::string& token);
  void logout(const std::string& token);
  // False when the session has used up its commands for the window.
  bool take_command(const std::string& token);

  // A secret as people type it: case, spaces and dashes do not matter.
  static std::string normalise(const std::string& secret);
  // A new random secret for the machine's label (20 letters and digits, in groups of 5).
  static std::string new_secret();
  // The first line of a secret's file. Throws config::ConfigError when the file cannot be read
  // and std::runtime_error, naming the file, when the secret is shorter than 12 letters.
  static std::string read_secret_file(const std::string& path);

 private:
  struct Session {
    Role role;
    std::string id, csrf;
    std::int64_t created_ns, last_ns;
    std::deque<std::int64_t> commands_ns;
  };
  void forget_old(std::deque<std::int64_t>& times, double window_s, std::int64_t now) const;

  Secrets secrets_;
  SessionPolicy policy_;
  Clock now_ns_;
  std::mutex mutex_;
  std::map<std::string, Session> sessions_;
  std::map<std::string, std::deque<std::int64_t>> failed_by_address_;
  std::map<std::string, std::deque<std::int64_t>> logins_by_address_;
  std::deque<std::int64_t> failed_all_;
};

}  // namespace planter::console
