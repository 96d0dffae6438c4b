#include "config/nmea.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace planter::config {

namespace {
constexpr double kKnotMps = 1852.0 / 3600.0;  // the international knot

// ddmm.mmmmm (or dddmm.mmmmm) and its hemisphere letter.
std::string angle_field(double deg, bool lat) {
  const double a = std::abs(deg);
  const int whole = static_cast<int>(a);
  const double minutes = (a - whole) * 60.0;
  char buf[32];
  std::snprintf(buf, sizeof buf, lat ? "%02d%08.5f,%c" : "%03d%08.5f,%c", whole, minutes,
                lat ? (deg < 0 ? 'S' : 'N') : (deg < 0 ? 'W' : 'E'));
  return buf;
}

std::string sentence(const std::string& body) {
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X\r\n", nmea_checksum(body));
  return "$" + body + tail;
}

std::vector<std::string_view> fields(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= s.size(); ++i) {
    if (i == s.size() || s[i] == ',') {
      out.push_back(s.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

bool number(std::string_view f, double& v) {
  if (f.empty() || f.size() > 32) return false;
  const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
  return r.ec == std::errc() && r.ptr == f.data() + f.size() && std::isfinite(v);
}

// ddmm.mmm (latitude, N or S) or dddmm.mmm (longitude, E or W) to degrees.
bool angle(std::string_view f, std::string_view hemi, bool lat, double& deg) {
  double raw = 0;
  if (!number(f, raw) || raw < 0 || hemi.size() != 1) return false;
  const double whole = std::floor(raw / 100.0);
  const double minutes = raw - whole * 100.0;
  deg = whole + minutes / 60.0;
  if (minutes >= 60.0 || deg > (lat ? 90.0 : 180.0)) return false;
  const char h = hemi[0];
  if (h == 'S' || h == 'W') deg = -deg;
  return lat ? (h == 'N' || h == 'S') : (h == 'E' || h == 'W');
}

// The body between '$' and '*' when the sentence is whole and its checksum right.
std::optional<std::string_view> checked_body(std::string_view line, std::string& why) {
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.remove_suffix(1);
  if (line.size() < 6 || line[0] != '$') {
    why = "not an NMEA sentence (no leading $)";
    return std::nullopt;
  }
  if (line.size() > 82) {
    why = "longer than NMEA's 82 characters";
    return std::nullopt;
  }
  const std::size_t star = line.rfind('*');
  if (star == std::string_view::npos || star + 3 != line.size()) {
    why = "no checksum (*hh at the end)";
    return std::nullopt;
  }
  unsigned given = 0;
  const auto r = std::from_chars(line.data() + star + 1, line.data() + line.size(), given, 16);
  const std::string_view body = line.substr(1, star - 1);
  if (r.ec != std::errc() || r.ptr != line.data() + line.size()) {
    why = "checksum is not two hex digits";
    return std::nullopt;
  }
  if (given != nmea_checksum(body)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "checksum %02X, the sentence's is %02X", given,
                  nmea_checksum(body));
    why = buf;
    return std::nullopt;
  }
  return body;
}
}  // namespace

std::uint8_t nmea_checksum(std::string_view body) {
  std::uint8_t x = 0;
  for (char c : body) x = static_cast<std::uint8_t>(x ^ static_cast<std::uint8_t>(c));
  return x;
}

std::string nmea_sentences(const hal::GnssFix& fix, double utc_s) {
  const auto whole = static_cast<std::time_t>(std::floor(utc_s));
  std::tm tm{};
  gmtime_r(&whole, &tm);
  char time[40], date[40];
  std::snprintf(time, sizeof time, "%02d%02d%05.2f", tm.tm_hour, tm.tm_min,
                tm.tm_sec + (utc_s - static_cast<double>(whole)));
  std::snprintf(date, sizeof date, "%02d%02d%02d", tm.tm_mday, tm.tm_mon + 1, tm.tm_year % 100);
  const bool fixed = hal::has_position(fix);
  std::string out;
  if (!fixed) {
    out += sentence(std::string("GPRMC,") + time + ",V,,,,,,," + date + ",,,N");
    out += sentence(std::string("GPGGA,") + time + ",,,,,0,00,99.9,,M,,M,,");
    return out;
  }
  char rmc[128], gga[128];
  std::snprintf(rmc, sizeof rmc, "GPRMC,%s,A,%s,%s,%.3f,%.2f,%s,,,A", time,
                angle_field(fix.lat_deg, true).c_str(), angle_field(fix.lon_deg, false).c_str(),
                fix.speed_mps / kKnotMps, fix.track_deg, date);
  std::snprintf(gga, sizeof gga, "GPGGA,%s,%s,%s,1,%02d,%.1f,30.0,M,0.0,M,,", time,
                angle_field(fix.lat_deg, true).c_str(), angle_field(fix.lon_deg, false).c_str(),
                fix.satellites, fix.hdop);
  return sentence(rmc) + sentence(gga);
}

namespace {
// An RMC sentence's fields, from its checked body.
std::optional<NmeaRmc> rmc_fields(std::string_view body, std::string& why) {
  const auto f = fields(body);
  if (f[0].size() != 5 || f[0].substr(2) != "RMC") {
    why = "not an RMC sentence";
    return std::nullopt;
  }
  if (f.size() < 10) {
    why = "RMC with fewer than 10 fields";
    return std::nullopt;
  }
  NmeaRmc r;
  double hms = 0;
  if (!number(f[1], hms) || hms < 0 || hms >= 240000) {
    why = "RMC time is not hhmmss.ss";
    return std::nullopt;
  }
  const double h = std::floor(hms / 10000), m = std::floor((hms - h * 10000) / 100);
  const double sec = hms - h * 10000 - m * 100;
  if (h > 23 || m > 59 || sec >= 61) {
    why = "RMC time is not hhmmss.ss";
    return std::nullopt;
  }
  r.time_of_day_s = h * 3600 + m * 60 + sec;
  r.valid = f[2] == "A";
  if (!r.valid) return r;
  double knots = 0;
  if (!angle(f[3], f[4], true, r.lat_deg) || !angle(f[5], f[6], false, r.lon_deg) ||
      !number(f[7], knots) || knots < 0) {
    why = "RMC position or speed is not a number";
    return std::nullopt;
  }
  r.speed_mps = knots * kKnotMps;
  if (!f[8].empty() && (!number(f[8], r.track_deg) || r.track_deg < 0 || r.track_deg > 360)) {
    why = "RMC track is not 0-360 degrees";
    return std::nullopt;
  }
  return r;
}
}  // namespace

std::optional<NmeaRmc> parse_nmea_rmc(std::string_view line, std::string& why) {
  const auto body = checked_body(line, why);
  if (!body) return std::nullopt;
  return rmc_fields(*body, why);
}

NmeaLogCheck check_nmea_log(std::istream& in, double max_speed_mps) {
  NmeaLogCheck c;
  const auto problem = [&c](std::size_t line, const std::string& what) {
    if (c.problems.size() < 20) c.problems.push_back("line " + std::to_string(line) + ": " + what);
    ++c.problem_count;
  };
  std::string line;
  double last_t = -1;
  while (std::getline(in, line)) {
    ++c.lines;
    if (line.empty() || line == "\r") continue;
    std::string why;
    const auto body = checked_body(line, why);
    if (!body) {
      problem(c.lines, why);
      continue;
    }
    ++c.sentences;
    if (body->size() < 5 || body->substr(2, 3) != "RMC") continue;
    const auto rmc = rmc_fields(*body, why);
    if (!rmc) {
      problem(c.lines, why);
      continue;
    }
    ++c.rmc;
    // A day's wrap is a time going on, not back.
    const double t = rmc->time_of_day_s + (last_t > 80000 && rmc->time_of_day_s < 6400 ? 86400 : 0);
    if (last_t >= 0 && t <= last_t) problem(c.lines, "RMC time stands still or runs back");
    if (last_t >= 0 && t - last_t > 10)
      problem(c.lines, "RMC time jumps " + std::to_string(t - last_t) + " s");
    last_t = rmc->time_of_day_s;
    if (!rmc->valid) continue;
    ++c.valid_fixes;
    c.max_speed_mps = std::max(c.max_speed_mps, rmc->speed_mps);
    if (rmc->speed_mps > max_speed_mps) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "speed %.3g m/s, above the machine's %.3g m/s", rmc->speed_mps,
                    max_speed_mps);
      problem(c.lines, buf);
    }
  }
  return c;
}

}  // namespace planter::config
