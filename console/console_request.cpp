#include "console/console_request.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>

namespace planter::console {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

std::string session_cookie(std::string_view cookies) {
  constexpr std::string_view key = "planter_session=";
  while (!cookies.empty()) {
    const std::size_t end = std::min(cookies.find(';'), cookies.size());
    std::string_view one = cookies.substr(0, end);
    while (!one.empty() && one.front() == ' ') one.remove_prefix(1);
    if (one.substr(0, key.size()) == key) return std::string(one.substr(key.size()));
    cookies.remove_prefix(std::min(end + 1, cookies.size()));
  }
  return {};
}

std::optional<std::string> login_secret(const std::string& body) {
  const auto j = nlohmann::json::parse(body, nullptr, false);
  if (!j.is_object() || !j.contains("secret") || !j["secret"].is_string()) return std::nullopt;
  return j["secret"].get<std::string>();
}

CommandBody parse_command_body(const std::string& body) {
  CommandBody c;
  const auto j = nlohmann::json::parse(body, nullptr, false);
  if (j.is_object() && j.contains("command") && j["command"].is_string())
    c.name = j["command"].get<std::string>();
  const bool has_value = j.is_object() && j.contains("value") && j["value"].is_number();
  if (has_value) {
    c.value = j["value"].get<double>();
    c.value_text = number_text(c.value);
  }
  if (!j.is_object() || !parse_command_name(c.name.c_str(), c.kind) ||
      c.name.size() != std::strlen(c.name.c_str())) {
    c.error =
        "send {\"command\": run | stop | fault_reset | set_depth_mm | set_clamp_force_N | "
        "record_start | record_stop, \"value\": number}";
    return c;
  }
  if (takes_value(c.kind) && (!has_value || !std::isfinite(c.value))) {
    c.error = c.name + " needs a number: \"value\"";
    return c;
  }
  if (!takes_value(c.kind)) c.value = 0.0;
  c.ok = true;
  return c;
}

std::string host_of(const std::string& host_header) {
  std::string h;
  for (char c : host_header)
    h.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  if (!h.empty() && h.front() == '[') {
    const auto end = h.find(']');
    return end == std::string::npos ? std::string() : h.substr(1, end - 1);
  }
  const auto colon = h.find(':');
  return colon == std::string::npos ? h : h.substr(0, colon);
}

}  // namespace planter::console
