#include "apps/planter-can/candump_log.h"

#include <cstdio>

#include "apps/planter-can/cia309_command.h"
#include "config/input_file.h"

namespace planter::cantool {
namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool parse_hex(std::string_view s, std::uint64_t& out) {
  if (s.empty() || s.size() > 16) return false;
  out = 0;
  for (char c : s) {
    const int v = hex_value(c);
    if (v < 0) return false;
    out = out * 16 + static_cast<std::uint64_t>(v);
  }
  return true;
}

bool parse_digits(std::string_view s, std::uint64_t& out) {
  if (s.empty() || s.size() > 18) return false;
  out = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    out = out * 10 + static_cast<std::uint64_t>(c - '0');
  }
  return true;
}

}  // namespace

std::string format_log_line(std::int64_t time_ns, std::string_view interface,
                            const hal::CanFrame& f) {
  char buf[128];
  const auto sec = static_cast<unsigned long>(time_ns / 1'000'000'000);
  const auto usec = static_cast<unsigned long>((time_ns % 1'000'000'000) / 1000);
  int n = std::snprintf(buf, sizeof buf, "(%010lu.%06lu) %.*s ", sec, usec,
                        static_cast<int>(interface.size()), interface.data());
  if (f.id & (hal::CanFrame::kExtendedFlag | hal::CanFrame::kErrorFlag)) {
    const std::uint32_t id = (f.id & 0x1FFFFFFFu) | (f.id & hal::CanFrame::kErrorFlag);
    n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "%08X#", id);
  } else {
    n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "%03X#", f.id & 0x7FFu);
  }
  if (f.id & hal::CanFrame::kRemoteFlag) {
    n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "R");
  } else {
    for (int i = 0; i < f.dlc && i < 8; ++i)
      n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "%02X",
                         f.data[static_cast<std::size_t>(i)]);
  }
  return std::string(buf, static_cast<std::size_t>(n));
}

LogParse parse_log_line(std::string_view line) {
  LogParse p;
  if (line.empty() || line[0] != '(') return p;  // comments, blank lines
  p.kind = LogLineKind::kError;
  const auto tokens = split_tokens(line);
  if (tokens.size() < 3) {
    p.error = "expected '(seconds.micro) interface id#data'";
    return p;
  }
  const std::string& ts = tokens[0];
  const std::size_t dot = ts.find('.');
  if (ts.back() != ')' || dot == std::string::npos) {
    p.error = "timestamp '" + config::excerpt(ts) + "' is not (seconds.microseconds)";
    return p;
  }
  std::uint64_t sec = 0;
  std::uint64_t frac = 0;
  const std::string_view frac_text(ts.data() + dot + 1, ts.size() - dot - 2);
  if (!parse_digits(std::string_view(ts).substr(1, dot - 1), sec) ||
      !parse_digits(frac_text, frac) || frac_text.size() > 9) {
    p.error = "timestamp '" + config::excerpt(ts) + "' is not (seconds.microseconds)";
    return p;
  }
  for (std::size_t k = frac_text.size(); k < 9; ++k) frac *= 10;
  if (sec > 9'000'000'000ull) {
    p.error = "timestamp '" + config::excerpt(ts) + "' is out of range";
    return p;
  }
  p.record.time_ns = static_cast<std::int64_t>(sec * 1'000'000'000ull + frac);
  p.record.interface = tokens[1];
  const std::string& fr = tokens[2];
  const std::size_t hash = fr.find('#');
  if (hash == std::string::npos || hash == 0) {
    p.error = "frame '" + config::excerpt(fr) + "' is not id#data";
    return p;
  }
  if (hash + 1 < fr.size() && fr[hash + 1] == '#') {
    p.error = "frame '" + config::excerpt(fr) + "' is CAN FD; this bus is classic CAN";
    return p;
  }
  std::uint64_t id = 0;
  const std::string_view id_text(fr.data(), hash);
  if (!parse_hex(id_text, id) || (id_text.size() != 3 && id_text.size() != 8) ||
      (id_text.size() == 3 && id > 0x7FF) || id > 0x3FFFFFFF) {
    p.error = "frame ID '" + config::excerpt(id_text) + "' is not 3 or 8 hex digits";
    return p;
  }
  hal::CanFrame& f = p.record.frame;
  if (id_text.size() == 8) {
    f.id = static_cast<std::uint32_t>(id & 0x1FFFFFFF);
    if (id & hal::CanFrame::kErrorFlag) {
      f.id |= hal::CanFrame::kErrorFlag;
    } else {
      f.id |= hal::CanFrame::kExtendedFlag;
    }
  } else {
    f.id = static_cast<std::uint32_t>(id);
  }
  std::string_view data(fr.data() + hash + 1, fr.size() - hash - 1);
  if (!data.empty() && (data[0] == 'R' || data[0] == 'r')) {
    f.id |= hal::CanFrame::kRemoteFlag;
    f.dlc = 0;
    if (data.size() == 2 && data[1] >= '0' && data[1] <= '8')
      f.dlc = static_cast<std::uint8_t>(data[1] - '0');
    p.kind = LogLineKind::kFrame;
    return p;
  }
  // Data bytes may be separated by dots (candump -L never writes them, cansend accepts them).
  std::string hex;
  for (char c : data) {
    if (c != '.') hex.push_back(c);
  }
  if (hex.size() % 2 != 0 || hex.size() > 16) {
    p.error = "frame data '" + config::excerpt(data) + "' is not 0-8 hex bytes";
    return p;
  }
  for (std::size_t i = 0; i < hex.size(); i += 2) {
    const int hi = hex_value(hex[i]);
    const int lo = hex_value(hex[i + 1]);
    if (hi < 0 || lo < 0) {
      p.error = "frame data '" + config::excerpt(data) + "' is not 0-8 hex bytes";
      return p;
    }
    f.data[i / 2] = static_cast<std::uint8_t>(hi * 16 + lo);
  }
  f.dlc = static_cast<std::uint8_t>(hex.size() / 2);
  p.kind = LogLineKind::kFrame;
  return p;
}

}  // namespace planter::cantool
