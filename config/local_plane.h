#pragma once
// Latitude and longitude to metres east and north of a point and back, on the plane tangent to
// a sphere of the Earth's mean radius there (an equirectangular projection: a row's tens of
// metres are far inside its error; Snyder, Map Projections, USGS PP 1395, 1987, p. 90). The
// simulated receiver places its fixes with it and the as-planted map reads them back.
#include <cmath>

namespace planter::config {

struct LocalPlane {
  static constexpr double kDeg = 0.017453292519943295;
  static constexpr double kEarthM = 6371000.0;  // mean radius
  double lat0_deg = 0, lon0_deg = 0;

  void to_local(double lat_deg, double lon_deg, double& east_m, double& north_m) const {
    north_m = (lat_deg - lat0_deg) * kDeg * kEarthM;
    east_m = (lon_deg - lon0_deg) * kDeg * kEarthM * std::cos(lat0_deg * kDeg);
  }
  void to_geo(double east_m, double north_m, double& lat_deg, double& lon_deg) const {
    lat_deg = lat0_deg + north_m / kEarthM / kDeg;
    lon_deg = lon0_deg + east_m / (kEarthM * std::cos(lat0_deg * kDeg)) / kDeg;
  }
};

}  // namespace planter::config
