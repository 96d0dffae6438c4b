#pragma once
// The row as planted, written as GeoJSON (RFC 7946): the receiver's track as a line and a
// point a seedling, with its spacing judged by the planting monitor's rule. planter-sim writes
// it from its simulated receiver, planterd from the board's. A seedling's place is the
// antenna's fix at its release less the antenna's offset along the row (the board's [gnss]
// antenna_ahead_m, antenna_left_m), so it is as good as the fix: metres standalone.
#include <optional>
#include <string>
#include <vector>

#include "firmware/sensing/planting_monitor.h"

namespace planter::config {

struct GeoPoint {
  double lat_deg = 0, lon_deg = 0;
};

struct PlantedSeedling {
  int number = 0;               // 1-based, in planting order
  double x_m = 0;               // along the row: the simulator's truth or the controller's distance
  GeoPoint place;               // the release point
  double spacing_mm = 0;        // the gap before it; NaN for the first of a stretch
  std::optional<bool> damaged;  // the simulator: past its first peak; planterd: not known
  double tilt_deg = 0;          // NaN where not known (planterd)
};

// The antenna's place moved back to the release point: the row's direction is the track's,
// from its first point to its last (a standalone fix's own track is noise at planting speed).
class AntennaOffset {
 public:
  AntennaOffset(const std::vector<GeoPoint>& track, double ahead_m, double left_m);
  [[nodiscard]] GeoPoint release_point(GeoPoint antenna) const;

 private:
  GeoPoint origin_;
  double ahead_m_, left_m_;
  double ue_ = 0, un_ = 0;  // the row's unit direction, east and north
};

std::string as_planted_geojson(const std::vector<GeoPoint>& track,
                               const std::vector<PlantedSeedling>& seedlings,
                               const PlantingMonitorConfig& monitor);

}  // namespace planter::config
