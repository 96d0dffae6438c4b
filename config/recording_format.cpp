#include "config/recording_format.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "firmware/io/signal_table.h"

namespace planter::config {

std::string controller_columns() {
  std::string head;
  for (const SignalDecl& s : kSignals) {
    if (!s.recorded) continue;
    if (!head.empty()) head += ',';
    head += s.column;
  }
  return head;
}

void RowText::text(std::string_view s) {
  if (total_ < size_) std::memcpy(out_ + total_, s.data(), std::min(s.size(), size_ - total_));
  total_ += s.size();
}

namespace {
constexpr std::array<double, 10> kPowersOfTen = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};

// "%.*f" through an integer when the rounding cannot be wrong: v * 10^decimals is off the
// exact product by at most half an ulp, so when its fraction is further than 2 ulp from
// one half, rounding it gives the exact decimal rounding. Near a tie (and for large or
// non-finite values) the caller falls back to std::to_chars. Returns the length, 0 if not
// written.
std::size_t fixed_by_integer(double v, int decimals, char* buf) {
  if (!std::isfinite(v) || decimals < 0 || decimals >= static_cast<int>(kPowersOfTen.size()))
    return 0;
  const double scaled = std::fabs(v) * kPowersOfTen[static_cast<std::size_t>(decimals)];
  if (!(scaled < 0x1p52)) return 0;
  const double whole = std::floor(scaled);
  const double fraction = scaled - whole;  // exact below 2^52
  if (std::fabs(fraction - 0.5) <= scaled * 0x1p-51) return 0;
  const auto digits_value = static_cast<std::uint64_t>(whole) + (fraction > 0.5 ? 1 : 0);
  char digits[24];
  const auto r = std::to_chars(digits, digits + sizeof digits, digits_value);
  const auto n = static_cast<std::size_t>(r.ptr - digits);
  const auto d = static_cast<std::size_t>(decimals);
  std::size_t at = 0;
  if (std::signbit(v)) buf[at++] = '-';  // printf keeps the sign of -0.0 and of -0.0001
  const auto put = [&](const char* from, std::size_t count) {
    std::memcpy(buf + at, from, count);
    at += count;
  };
  if (d == 0) {
    put(digits, n);
  } else if (n > d) {
    put(digits, n - d);
    buf[at++] = '.';
    put(digits + (n - d), d);
  } else {
    buf[at++] = '0';
    buf[at++] = '.';
    for (std::size_t i = n; i < d; ++i) buf[at++] = '0';
    put(digits, n);
  }
  return at;
}
}  // namespace

void RowText::fixed(double v, int decimals) {
  // The longest "%.*f" of a double: 309 integer digits, a sign, a point and the decimals.
  char buf[320 + 32];
  if (const std::size_t n = fixed_by_integer(v, decimals, buf); n > 0) {
    text(std::string_view(buf, n));
    return;
  }
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed,
                               std::clamp(decimals, 0, 30));
  text(r.ec == std::errc{} ? std::string_view(buf, static_cast<std::size_t>(r.ptr - buf))
                           : std::string_view("nan"));
}

void RowText::integer(long long v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  text(std::string_view(buf, static_cast<std::size_t>(r.ptr - buf)));
}

int format_controller_columns(char* out, std::size_t size, double t_s, const Telemetry& c) {
  RowText row(out, size);
  bool first = true;
  for (const SignalDecl& s : kSignals) {
    if (!s.recorded) continue;
    if (!first) row.separator();
    first = false;
    if (s.source == SignalSource::kClock) {
      row.fixed(t_s, s.decimals);
    } else if (s.source == SignalSource::kSupervisor) {
      row.text(supervisor_state_name(c.state));
    } else if (s.source == SignalSource::kWarnings) {
      row.integer(static_cast<long long>(c.warnings));
    } else if (s.monitored != nullptr) {
      row.fixed(c.planting.*s.monitored, s.decimals);
    } else if (s.measured != nullptr) {
      row.fixed(c.*s.measured, s.decimals);
    } else if (s.commanded != nullptr) {
      row.fixed(c.*s.commanded, s.decimals);
    } else {  // the encoder's count
      row.integer(static_cast<long long>(c.wheel_counts));
    }
  }
  // Like snprintf: the terminator when there is room for it.
  if (row.length() < size) {
    out[row.length()] = '\0';
  } else if (size > 0) {
    out[size - 1] = '\0';
  }
  return static_cast<int>(row.length());
}

std::string sync_period_value(std::int64_t sync_period_ns) {
  char value[32];
  std::snprintf(value, sizeof value, "%.9g", static_cast<double>(sync_period_ns) * 1e-9);
  return value;
}

}  // namespace planter::config
