#pragma once
// NMEA 0183 sentences for a GNSS receiver's fixes (NMEA 0183 v4.10; gpsd's NMEA page names
// the fields): the simulator writes RMC and GGA for each of its receiver's fixes, so gpsfake
// and any NMEA tool can replay its run, and the reader checks a receiver's log before it is
// trusted: checksums, a time that stands still or jumps, a speed no planter makes.
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "planter/hal/gnss.h"

namespace planter::config {

// The XOR of the characters between '$' and '*' (NMEA 0183 section 5.3.1).
std::uint8_t nmea_checksum(std::string_view body);

// RMC and GGA for one fix, at `utc_s` seconds since 1970-01-01 UTC (CRLF line ends).
std::string nmea_sentences(const hal::GnssFix& fix, double utc_s);

// One RMC sentence, read. nullopt with `why` when it is not one, or not whole.
struct NmeaRmc {
  double time_of_day_s = 0;  // hhmmss.ss
  bool valid = false;        // status A
  double speed_mps = 0;
  double track_deg = 0;
  double lat_deg = 0, lon_deg = 0;
};
std::optional<NmeaRmc> parse_nmea_rmc(std::string_view line, std::string& why);

// A log checked sentence by sentence (checksums of every sentence, RMC's time and speed).
struct NmeaLogCheck {
  std::size_t lines = 0, sentences = 0, rmc = 0, valid_fixes = 0;
  double max_speed_mps = 0;
  std::vector<std::string> problems;  // "line N: what", the first 20
  std::size_t problem_count = 0;
};
// `max_speed_mps`: a speed above it is flagged (the machine's plausible ground speed).
NmeaLogCheck check_nmea_log(std::istream& in, double max_speed_mps);

}  // namespace planter::config
