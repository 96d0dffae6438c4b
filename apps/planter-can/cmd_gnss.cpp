#include "apps/planter-can/cmd_gnss.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>

#include "config/nmea.h"
#include "firmware/sensing/ground_fusion.h"
#include "hal/linux/gpsd_receiver.h"
#include "hal/linux/monotonic_clock.h"

namespace planter::cantool {

namespace {
// The receiver's time of the fix as hh:mm:ss.ss UTC, or "--:--:--.--" when it gave none.
[[maybe_unused]] std::string utc_of_day(double unix_s) {
  if (!(unix_s > 0)) return "--:--:--.-- UTC";
  const double day_s = std::fmod(unix_s, 86400.0);
  const int h = static_cast<int>(day_s / 3600), m = static_cast<int>(std::fmod(day_s, 3600) / 60);
  char text[32];
  std::snprintf(text, sizeof text, "%02d:%02d:%05.2f UTC", h, m, std::fmod(day_s, 60.0));
  return text;
}

int check_log(const std::string& path, double max_speed_mps, std::ostream& out, std::ostream& err) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    err << "planter-can: gnss --log " << path << ": cannot be read\n";
    return 1;
  }
  const config::NmeaLogCheck c = config::check_nmea_log(in, max_speed_mps);
  char line[256];
  std::snprintf(line, sizeof line,
                "%s: %zu lines, %zu sentences with good checksums, %zu RMC, %zu fixes, fastest "
                "%.3f m/s\n",
                path.c_str(), c.lines, c.sentences, c.rmc, c.valid_fixes, c.max_speed_mps);
  out << line;
  for (const std::string& p : c.problems) out << "  " << p << "\n";
  if (c.problem_count > c.problems.size())
    out << "  ... and " << c.problem_count - c.problems.size() << " more\n";
  out << (c.problem_count == 0 && c.valid_fixes > 0
              ? "gnss log: clean\n"
              : "gnss log: " + std::to_string(c.problem_count) + " problems, " +
                    std::to_string(c.valid_fixes) + " fixes\n");
  return c.problem_count == 0 && c.valid_fixes > 0 ? 0 : 1;
}

}  // namespace

int run_gnss(const config::BoardConfig* board, const GnssOptions& o, std::ostream& out,
             std::ostream& err) {
  GroundFusionConfig fusion = board ? board->controller.ground : GroundFusionConfig{};
  fusion.gnss_fitted = true;
  if (!o.log_path.empty()) return check_log(o.log_path, fusion.max_speed_mps, out, err);
#ifndef PLANTER_HAVE_GPSD
  err << "planter-can: gnss: this build has no gpsd library (libgps-dev); --log still checks "
         "a receiver's NMEA log\n";
  return 2;
#else
  hal::linux_backend::GpsdOptions g;
  g.host = !o.host.empty() ? o.host : board ? board->gnss.gpsd_host : "127.0.0.1";
  g.port = o.port != 0 ? o.port : board ? board->gnss.gpsd_port : 2947;
  using hal::linux_backend::monotonic_now_ns;
  hal::linux_backend::GpsdReceiver receiver(g, [] { return monotonic_now_ns(); });
  hal::GnssFix fix;
  std::int64_t last_taken_ns = 0;
  const std::int64_t t0 = monotonic_now_ns();
  const auto end = static_cast<std::int64_t>(o.duration_s * 1e9);
  std::uint64_t seen = 0, used = 0;
  int counts[7] = {};
  while (monotonic_now_ns() - t0 < end && !(o.stop && o.stop->load())) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const std::int64_t now = monotonic_now_ns();
    if (!receiver.latest(fix) || fix.sequence == seen) continue;
    seen = fix.sequence;
    const GnssUse use = judge_fix(fusion, fix, last_taken_ns);
    if (use == GnssUse::kUsing) last_taken_ns = fix.valid_ns;
    ++counts[static_cast<int>(use)];
    used += use == GnssUse::kUsing ? 1 : 0;
    char line[200];
    std::snprintf(line, sizeof line,
                  "%7.2f s  %s  mode %d  %2d sats  HDOP %4.1f  %7.3f m/s  track %6.1f  %s\n",
                  static_cast<double>(now - t0) * 1e-9, utc_of_day(fix.receiver_time_s).c_str(),
                  static_cast<int>(fix.mode), fix.satellites, fix.hdop, fix.speed_mps,
                  fix.track_deg, gnss_use_name(use));
    out << line << std::flush;
  }
  out << "gnss: gpsd at " << g.host << ":" << g.port << " "
      << (receiver.connections() ? "connected" : "never connected") << ", " << seen << " fixes, "
      << used << " usable";
  // The fusion's own words for what was not: no fix, poor, stale, refused.
  for (int u = 2; u < 7; ++u)
    if (counts[u]) out << ", " << counts[u] << " " << gnss_use_name(static_cast<GnssUse>(u));
  out << "\n";
  return used > 0 ? 0 : 1;
#endif
}

}  // namespace planter::cantool
