#include "apps/planter-sim/as_planted.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "config/as_planted.h"
#include "config/local_plane.h"

namespace planter::sim {

namespace {
// The fix's place at t, between the two fixes around it (both fixed, at most 1 s apart).
bool place_at(const std::vector<hal::GnssFix>& fixes, std::int64_t t_ns, double& lat, double& lon) {
  const auto after =
      std::lower_bound(fixes.begin(), fixes.end(), t_ns,
                       [](const hal::GnssFix& f, std::int64_t t) { return f.valid_ns < t; });
  if (after == fixes.end() || after == fixes.begin()) return false;
  const hal::GnssFix& b = *after;
  const hal::GnssFix& a = *(after - 1);
  if (!hal::has_position(a) || !hal::has_position(b) || b.valid_ns - a.valid_ns > 1'000'000'000)
    return false;
  const double f =
      static_cast<double>(t_ns - a.valid_ns) / static_cast<double>(b.valid_ns - a.valid_ns);
  lat = a.lat_deg + f * (b.lat_deg - a.lat_deg);
  lon = a.lon_deg + f * (b.lon_deg - a.lon_deg);
  return true;
}

// Spacing before each released seedling in the ground (mm; NaN for the first or one that fell).
std::vector<double> gaps_mm(const SeedlingProcess& seedlings) {
  std::vector<double> gaps(seedlings.released(), std::nan(""));
  double last_x = std::nan("");
  for (std::size_t i = 0; i < seedlings.released(); ++i) {
    const Seedling& s = seedlings.seedlings()[i];
    if (s.release.fell_in_carry) continue;
    if (std::isfinite(last_x)) gaps[i] = (s.x_m - last_x) * 1000.0;
    last_x = s.x_m;
  }
  return gaps;
}

// The fixes that place the antenna, as the row's track.
std::vector<config::GeoPoint> track_of(const std::vector<hal::GnssFix>& fixes) {
  std::vector<config::GeoPoint> track;
  for (const hal::GnssFix& f : fixes)
    if (hal::has_position(f)) track.push_back({f.lat_deg, f.lon_deg});
  return track;
}
}  // namespace

std::vector<PlantedPlace> place_seedlings(const SeedlingProcess& seedlings,
                                          const std::vector<hal::GnssFix>& fixes,
                                          const config::GnssBoardConfig& antenna) {
  std::vector<PlantedPlace> places(seedlings.released());
  const std::vector<config::GeoPoint> track = track_of(fixes);
  if (track.empty()) return places;
  const config::LocalPlane plane{track.front().lat_deg, track.front().lon_deg};
  const config::AntennaOffset offset(track, antenna.antenna_ahead_m, antenna.antenna_left_m);
  for (std::size_t i = 0; i < places.size(); ++i) {
    const Seedling& s = seedlings.seedlings()[i];
    config::GeoPoint at;
    if (s.release.fell_in_carry ||
        !place_at(fixes, static_cast<std::int64_t>(s.release_time_s * 1e9), at.lat_deg, at.lon_deg))
      continue;
    PlantedPlace& p = places[i];
    const config::GeoPoint release = offset.release_point(at);
    p.lat_deg = release.lat_deg, p.lon_deg = release.lon_deg;
    plane.to_local(p.lat_deg, p.lon_deg, p.east_m, p.north_m);
    p.known = true;
  }
  return places;
}

std::string as_planted_geojson(const SeedlingProcess& seedlings,
                               const std::vector<PlantedPlace>& places,
                               const std::vector<hal::GnssFix>& fixes,
                               const PlantingMonitorConfig& monitor) {
  const std::vector<double> gaps = gaps_mm(seedlings);
  std::vector<config::PlantedSeedling> planted;
  for (std::size_t i = 0; i < places.size(); ++i) {
    if (!places[i].known) continue;
    const Seedling& s = seedlings.seedlings()[i];
    planted.push_back({static_cast<int>(i + 1),
                       s.x_m,
                       {places[i].lat_deg, places[i].lon_deg},
                       gaps[i],
                       s.damaged,
                       s.tilt_deg});
  }
  return config::as_planted_geojson(track_of(fixes), planted, monitor);
}

std::string as_planted_svg(const SeedlingProcess& seedlings,
                           const std::vector<PlantedPlace>& places,
                           const PlantingMonitorConfig& monitor) {
  double e0 = 1e300, e1 = -1e300, n0 = 1e300, n1 = -1e300;
  for (const PlantedPlace& p : places) {
    if (!p.known) continue;
    e0 = std::min(e0, p.east_m), e1 = std::max(e1, p.east_m);
    n0 = std::min(n0, p.north_m), n1 = std::max(n1, p.north_m);
  }
  if (e0 > e1) return "<p>No seedling has a GNSS place: no fix at their release.</p>";
  const double pad = 1.0, width = 800.0;
  const double span = std::max({e1 - e0, n1 - n0, 1.0}) + 2 * pad;
  const double scale = (width - 80) / span;  // px per metre, the same both ways
  const double height = std::max(120.0, (n1 - n0 + 2 * pad) * scale + 80);
  const auto x = [&](double e) { return 60 + (e - e0 + pad) * scale; };
  const auto y = [&](double n) { return height - 50 - (n - n0 + pad) * scale; };
  std::ostringstream svg;
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "<svg viewBox='0 0 %.0f %.0f' style='width:100%%;max-width:%.0fpx' role='img' "
                "aria-label='the row as planted, in local metres'>",
                width, height, width);
  svg << buf;
  std::snprintf(buf, sizeof buf,
                "<text x='60' y='%.0f' font-size='24'>east [m], %.0f m across; north up, the "
                "same scale</text>",
                height - 12, span);
  svg << buf;
  const std::vector<double> gaps = gaps_mm(seedlings);
  int skips = 0, multiples = 0;
  for (std::size_t i = 0; i < places.size(); ++i) {
    if (!places[i].known) continue;
    const bool skip = std::isfinite(gaps[i]) && monitor.is_skip(gaps[i]);
    const bool multiple = std::isfinite(gaps[i]) && monitor.is_multiple(gaps[i]);
    skips += skip, multiples += multiple;
    const char* colour = skip ? "#c00" : multiple ? "#06c" : "#2a2";
    std::snprintf(buf, sizeof buf, "<circle cx='%.1f' cy='%.1f' r='%d' fill='%s'/>",
                  x(places[i].east_m), y(places[i].north_m), skip || multiple ? 6 : 3, colour);
    svg << buf;
  }
  svg << "</svg><p>Green: a seedling; red: the seedling after a skip (" << skips
      << "); blue: a multiple (" << multiples
      << "). Each place is the receiver's fix at its release less the antenna's offset, so it "
         "is as good as the fix: metres for a standalone receiver, centimetres with RTK.</p>";
  return svg.str();
}

}  // namespace planter::sim
