#include "config/as_planted.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "config/local_plane.h"

namespace planter::config {

AntennaOffset::AntennaOffset(const std::vector<GeoPoint>& track, double ahead_m, double left_m)
    : origin_(track.empty() ? GeoPoint{} : track.front()), ahead_m_(ahead_m), left_m_(left_m) {
  if (track.empty()) return;
  double de = 0, dn = 0;
  LocalPlane{origin_.lat_deg, origin_.lon_deg}.to_local(track.back().lat_deg, track.back().lon_deg,
                                                        de, dn);
  const double len = std::hypot(de, dn);
  if (len > 0) ue_ = de / len, un_ = dn / len;
}

GeoPoint AntennaOffset::release_point(GeoPoint antenna) const {
  const LocalPlane plane{origin_.lat_deg, origin_.lon_deg};
  double e = 0, n = 0;
  plane.to_local(antenna.lat_deg, antenna.lon_deg, e, n);
  e -= ahead_m_ * ue_ - left_m_ * un_;
  n -= ahead_m_ * un_ + left_m_ * ue_;
  GeoPoint p;
  plane.to_geo(e, n, p.lat_deg, p.lon_deg);
  return p;
}

std::string as_planted_geojson(const std::vector<GeoPoint>& track,
                               const std::vector<PlantedSeedling>& seedlings,
                               const PlantingMonitorConfig& monitor) {
  using nlohmann::ordered_json;
  const auto number_or_null = [](double v) {
    return std::isfinite(v) ? ordered_json(v) : ordered_json();
  };
  ordered_json line = ordered_json::array();
  for (const GeoPoint& p : track) line.push_back({p.lon_deg, p.lat_deg});
  ordered_json features = ordered_json::array();
  features.push_back({{"type", "Feature"},
                      {"geometry", {{"type", "LineString"}, {"coordinates", line}}},
                      {"properties", {{"what", "the GNSS receiver's track"}}}});
  for (const PlantedSeedling& s : seedlings) {
    const bool gap = std::isfinite(s.spacing_mm);
    ordered_json props = {{"seedling", s.number}, {"x_m", s.x_m}};
    props["spacing_mm"] = number_or_null(s.spacing_mm);
    props["skip"] = gap && monitor.is_skip(s.spacing_mm);
    props["multiple"] = gap && monitor.is_multiple(s.spacing_mm);
    props["damaged"] = s.damaged ? ordered_json(*s.damaged) : ordered_json();
    props["tilt_deg"] = number_or_null(s.tilt_deg);
    features.push_back(
        {{"type", "Feature"},
         {"geometry", {{"type", "Point"}, {"coordinates", {s.place.lon_deg, s.place.lat_deg}}}},
         {"properties", props}});
  }
  return ordered_json{{"type", "FeatureCollection"}, {"features", features}}.dump() + "\n";
}

}  // namespace planter::config
