// Fuzz target: a receiver's NMEA log (config/nmea.h). Reading it line by line and each line as
// an RMC either yields figures that are finite and in range, or a reason; never a crash, a
// read past the input, or a NaN let through.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>

#include "config/nmea.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream in(text);
  const planter::config::NmeaLogCheck c = planter::config::check_nmea_log(in, 1.0);
  if (c.rmc > c.sentences || c.valid_fixes > c.rmc || !std::isfinite(c.max_speed_mps)) std::abort();
  std::istringstream lines(text);
  std::string line, why;
  while (std::getline(lines, line)) {
    const auto r = planter::config::parse_nmea_rmc(line, why);
    if (!r) {
      if (why.empty()) std::abort();  // refused without a reason
      continue;
    }
    if (!std::isfinite(r->speed_mps) || r->speed_mps < 0 || r->time_of_day_s < 0 ||
        r->time_of_day_s >= 86400 + 61 || std::abs(r->lat_deg) > 90 || std::abs(r->lon_deg) > 180 ||
        r->track_deg > 360)
      std::abort();
  }
  return 0;
}
