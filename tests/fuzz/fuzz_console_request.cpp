// Fuzz target: what the console reads from the network: the Cookie header, the Host header, the
// login's and the command's JSON bodies. Every body is a command or an error that says something; a
// command's value is finite where it has one; a cookie's value never holds the separator.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "console/console_request.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace planter::console;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string cookie = session_cookie(text);
  if (cookie.find(';') != std::string::npos) __builtin_trap();
  (void)login_secret(text);
  const CommandBody c = parse_command_body(text);
  if (!c.ok && c.error.empty()) __builtin_trap();
  if (c.ok && takes_value(c.kind) && !std::isfinite(c.value)) __builtin_trap();
  if (c.ok && c.name != command_name(c.kind)) __builtin_trap();
  // The Host header's name: lower case, and no port left on it (an IPv6 address in brackets
  // keeps its colons, without the brackets).
  const std::string host = host_of(text);
  for (char ch : host)
    if (ch >= 'A' && ch <= 'Z') __builtin_trap();
  if ((text.empty() || text[0] != '[') && host.find(':') != std::string::npos) __builtin_trap();
  if (host.find(']') != std::string::npos && !text.empty() && text[0] == '[') __builtin_trap();
  return 0;
}
