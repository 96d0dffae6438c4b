#include "console/operator_sessions.h"

#include <sys/random.h>

#include <algorithm>
#include <cctype>
#include <iterator>
#include <stdexcept>

#include "config/input_file.h"

namespace planter::console {
namespace {
// A phone per person on the field is plenty; operators have their own slots.
constexpr std::size_t kOperatorSessionsMax = 8;
constexpr std::size_t kViewerSessionsMax = 56;

// Forgets the addresses whose times have all left the window, once there are many.
void prune(std::map<std::string, std::deque<std::int64_t>>& by_address,
           const std::function<void(std::deque<std::int64_t>&)>& forget) {
  if (by_address.size() <= 4096) return;
  for (auto it = by_address.begin(); it != by_address.end();) {
    forget(it->second);
    it = it->second.empty() ? by_address.erase(it) : std::next(it);
  }
}

std::string random_text(std::size_t n, const char* alphabet, std::size_t alphabet_size) {
  std::string out;
  while (out.size() < n) {
    unsigned char bytes[32];
    if (getrandom(bytes, sizeof bytes, 0) != static_cast<ssize_t>(sizeof bytes))
      throw std::runtime_error("console: no random numbers from the kernel (getrandom)");
    // Rejection sampling keeps every letter equally likely.
    const std::size_t limit = 256 - 256 % alphabet_size;
    for (unsigned char b : bytes)
      if (b < limit && out.size() < n) out.push_back(alphabet[b % alphabet_size]);
  }
  return out;
}
std::string token() { return random_text(43, "0123456789abcdef", 16); }

// Same time whatever matches, so the answer's delay tells nothing of the secret.
bool same_secret(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  unsigned diff = a.size() == b.size() ? 0u : 1u;
  for (std::size_t i = 0; i < a.size(); ++i)
    diff |= static_cast<unsigned char>(a[i]) ^ static_cast<unsigned char>(b[i % b.size()]);
  return diff == 0;
}
}  // namespace

const char* role_name(Role role) {
  switch (role) {
    case Role::kNone:
      return "none";
    case Role::kViewer:
      return "viewer";
    case Role::kOperator:
      return "operator";
  }
  return "none";
}

OperatorSessions::OperatorSessions(Secrets secrets, SessionPolicy policy, Clock now_ns)
    : secrets_{normalise(secrets.pairing), normalise(secrets.viewer)},
      policy_(policy),
      now_ns_(std::move(now_ns)) {}

std::string OperatorSessions::normalise(const std::string& secret) {
  std::string out;
  for (char c : secret)
    if (c != '-' && !std::isspace(static_cast<unsigned char>(c)))
      out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  return out;
}

std::string OperatorSessions::new_secret() {
  // No 0/o, 1/l/i: read off a label in the sun.
  const std::string letters = random_text(20, "23456789abcdefghjkmnpqrstuvwxyz", 31);
  std::string out;
  for (std::size_t i = 0; i < letters.size(); ++i) {
    if (i > 0 && i % 5 == 0) out.push_back('-');
    out.push_back(letters[i]);
  }
  return out;
}

std::string OperatorSessions::read_secret_file(const std::string& path) {
  std::string text = config::read_input_file(path, 4096);
  text = text.substr(0, text.find('\n'));
  if (normalise(text).size() < kSecretLettersMin)
    throw std::runtime_error(path + ": a secret needs at least 12 letters or digits");
  return text;
}

void OperatorSessions::forget_old(std::deque<std::int64_t>& times, double window_s,
                                  std::int64_t now) const {
  const auto window_ns = static_cast<std::int64_t>(window_s * 1e9);
  while (!times.empty() && now - times.front() >= window_ns) times.pop_front();
}

LoginResult OperatorSessions::login(const std::string& address, const std::string& secret) {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::int64_t now = now_ns_();
  const auto forget = [&](std::deque<std::int64_t>& t) {
    forget_old(t, policy_.login_window_s, now);
  };
  prune(failed_by_address_, forget);
  prune(logins_by_address_, forget);
  auto& mine = failed_by_address_[address];
  forget(mine);
  forget(failed_all_);
  LoginResult result;
  const auto wait_from = [&](std::int64_t oldest) {
    return std::max(1.0, policy_.login_window_s - static_cast<double>(now - oldest) * 1e-9);
  };
  // This address has guessed enough: refused whatever it sends, until its window has passed.
  if (static_cast<int>(mine.size()) >= policy_.failed_logins_per_address) {
    result.status = LoginResult::Status::kRateLimited;
    result.retry_after_s = wait_from(mine.front());
    return result;
  }
  const std::string typed = normalise(secret);
  Role role = Role::kNone;
  if (same_secret(typed, secrets_.pairing)) {
    role = Role::kOperator;
  } else if (same_secret(typed, secrets_.viewer)) {
    role = Role::kViewer;
  }
  if (role == Role::kNone) {
    mine.push_back(now);
    if (static_cast<int>(failed_all_.size()) >= policy_.failed_logins_total) {
      result.status = LoginResult::Status::kRateLimited;
      result.retry_after_s = wait_from(failed_all_.front());
    } else {
      result.status = LoginResult::Status::kWrongSecret;
      failed_all_.push_back(now);
    }
    return result;
  }
  auto& logins = logins_by_address_[address];
  forget(logins);
  if (static_cast<int>(logins.size()) >= policy_.logins_per_address) {
    result.status = LoginResult::Status::kTooManyLogins;
    result.retry_after_s = wait_from(logins.front());
    return result;
  }
  logins.push_back(now);
  // The oldest session of the same role gives way when its slots are full.
  const std::size_t slots = role == Role::kOperator ? kOperatorSessionsMax : kViewerSessionsMax;
  std::size_t same_role = 0;
  auto oldest = sessions_.end();
  for (auto it = sessions_.begin(); it != sessions_.end(); ++it) {
    if (it->second.role != role) continue;
    ++same_role;
    if (oldest == sessions_.end() || it->second.last_ns < oldest->second.last_ns) oldest = it;
  }
  if (same_role >= slots && oldest != sessions_.end()) sessions_.erase(oldest);
  result.status = LoginResult::Status::kOk;
  result.role = role;
  result.token = token();
  result.csrf = token();
  result.id = token().substr(0, 8);
  sessions_[result.token] = Session{role, result.id, result.csrf, now, now, {}};
  return result;
}

std::optional<SessionView> OperatorSessions::find(const std::string& token_text) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = sessions_.find(token_text);
  if (it == sessions_.end()) return std::nullopt;
  const std::int64_t now = now_ns_();
  Session& s = it->second;
  if (static_cast<double>(now - s.last_ns) * 1e-9 >= policy_.idle_s ||
      static_cast<double>(now - s.created_ns) * 1e-9 >= policy_.max_s) {
    sessions_.erase(it);
    return std::nullopt;
  }
  s.last_ns = now;
  return SessionView{s.role, s.id, s.csrf};
}

void OperatorSessions::logout(const std::string& token_text) {
  std::lock_guard<std::mutex> lock(mutex_);
  sessions_.erase(token_text);
}

bool OperatorSessions::take_command(const std::string& token_text) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = sessions_.find(token_text);
  if (it == sessions_.end()) return false;
  const std::int64_t now = now_ns_();
  auto& times = it->second.commands_ns;
  forget_old(times, policy_.command_window_s, now);
  if (static_cast<int>(times.size()) >= policy_.commands_per_window) return false;
  times.push_back(now);
  return true;
}

}  // namespace planter::console
