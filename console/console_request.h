#pragma once
// What a console request carries, read from the network's bytes: the session cookie, the
// login's secret and the command's JSON. Each says what is wrong when it is wrong; none
// trusts a length, a type or an encoding it was sent. Fuzzed (tests/fuzz/fuzz_console_request).
#include <optional>
#include <string>
#include <string_view>

#include "console/command_channel.h"

namespace planter::console {

// The value of the `planter_session` cookie in a Cookie header, or "" when there is none.
std::string session_cookie(std::string_view cookie_header);

// The secret in {"secret": "..."}, or nothing.
std::optional<std::string> login_secret(const std::string& body);

// A number as the console says it back (and logs it): "%g".
std::string number_text(double v);

struct CommandBody {
  bool ok = false;
  ConsoleCommandKind kind = ConsoleCommandKind::kStop;
  double value = 0.0;
  std::string name = "command";  // as sent, for the audit log
  std::string value_text = "-";  // as read, for the audit log
  std::string error;             // when !ok: what to send instead
};
// {"command": NAME, "value": NUMBER}; the value is needed by the set-points, and must be finite.
CommandBody parse_command_body(const std::string& body);

// The name in a Host header: "name:port" -> "name", "[::1]:80" -> "::1", in lower case.
std::string host_of(const std::string& host_header);

}  // namespace planter::console
