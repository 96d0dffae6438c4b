#include "apps/planter-sim/as_planted.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "sim/plant/local_plane.h"

namespace planter::sim {

namespace {
bool fixed(const hal::GnssFix& f) {
  return f.mode == hal::GnssMode::k2D || f.mode == hal::GnssMode::k3D;
}

// The fix's place at t, between the two fixes around it (both fixed, at most 1 s apart).
bool place_at(const std::vector<hal::GnssFix>& fixes, std::int64_t t_ns, double& lat, double& lon) {
  const auto after =
      std::lower_bound(fixes.begin(), fixes.end(), t_ns,
                       [](const hal::GnssFix& f, std::int64_t t) { return f.valid_ns < t; });
  if (after == fixes.end() || after == fixes.begin()) return false;
  const hal::GnssFix& b = *after;
  const hal::GnssFix& a = *(after - 1);
  if (!fixed(a) || !fixed(b) || b.valid_ns - a.valid_ns > 1'000'000'000) return false;
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
}  // namespace

std::vector<PlantedPlace> place_seedlings(const SeedlingProcess& seedlings,
                                          const std::vector<hal::GnssFix>& fixes,
                                          const config::GnssBoardConfig& antenna) {
  std::vector<PlantedPlace> places(seedlings.released());
  const auto first = std::find_if(fixes.begin(), fixes.end(), fixed);
  const auto last = std::find_if(fixes.rbegin(), fixes.rend(), fixed);
  if (first == fixes.end()) return places;
  const LocalPlane plane{first->lat_deg, first->lon_deg};
  // The row's direction from its first fix to its last: the antenna's offset is along it.
  double de = 0, dn = 0;
  plane.to_local(last->lat_deg, last->lon_deg, de, dn);
  const double len = std::hypot(de, dn);
  const double ue = len > 0 ? de / len : 0, un = len > 0 ? dn / len : 0;
  for (std::size_t i = 0; i < places.size(); ++i) {
    const Seedling& s = seedlings.seedlings()[i];
    double lat = 0, lon = 0;
    if (s.release.fell_in_carry ||
        !place_at(fixes, static_cast<std::int64_t>(s.release_time_s * 1e9), lat, lon))
      continue;
    PlantedPlace& p = places[i];
    plane.to_local(lat, lon, p.east_m, p.north_m);
    p.east_m -= antenna.antenna_ahead_m * ue - antenna.antenna_left_m * un;
    p.north_m -= antenna.antenna_ahead_m * un + antenna.antenna_left_m * ue;
    plane.to_geo(p.east_m, p.north_m, p.lat_deg, p.lon_deg);
    p.known = true;
  }
  return places;
}

std::string as_planted_geojson(const SeedlingProcess& seedlings,
                               const std::vector<PlantedPlace>& places,
                               const std::vector<hal::GnssFix>& fixes,
                               const PlantingMonitorConfig& monitor) {
  using nlohmann::ordered_json;
  ordered_json track = ordered_json::array();
  for (const hal::GnssFix& f : fixes)
    if (fixed(f)) track.push_back({f.lon_deg, f.lat_deg});
  ordered_json features = ordered_json::array();
  features.push_back({{"type", "Feature"},
                      {"geometry", {{"type", "LineString"}, {"coordinates", track}}},
                      {"properties", {{"what", "the GNSS receiver's track"}}}});
  const std::vector<double> gaps = gaps_mm(seedlings);
  for (std::size_t i = 0; i < places.size(); ++i) {
    if (!places[i].known) continue;
    const Seedling& s = seedlings.seedlings()[i];
    ordered_json props = {{"seedling", i + 1}, {"x_m", s.x_m}};
    props["spacing_mm"] = std::isfinite(gaps[i]) ? ordered_json(gaps[i]) : ordered_json();
    props["skip"] =
        std::isfinite(gaps[i]) && gaps[i] > monitor.skip_ratio * monitor.target_spacing_mm;
    props["multiple"] =
        std::isfinite(gaps[i]) && gaps[i] <= monitor.multiple_ratio * monitor.target_spacing_mm;
    props["damaged"] = s.damaged;
    props["tilt_deg"] = s.tilt_deg;
    features.push_back(
        {{"type", "Feature"},
         {"geometry", {{"type", "Point"}, {"coordinates", {places[i].lon_deg, places[i].lat_deg}}}},
         {"properties", props}});
  }
  return ordered_json{{"type", "FeatureCollection"}, {"features", features}}.dump() + "\n";
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
    const bool skip =
        std::isfinite(gaps[i]) && gaps[i] > monitor.skip_ratio * monitor.target_spacing_mm;
    const bool multiple =
        std::isfinite(gaps[i]) && gaps[i] <= monitor.multiple_ratio * monitor.target_spacing_mm;
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
