#pragma once
// Where each seedling went in the ground as the machine's GNSS receiver places it: the
// antenna's fix at the seedling's release, interpolated between fixes, less the antenna's
// offset from the release (the board's [gnss] antenna_ahead_m, antenna_left_m). Written as
// seedlings.csv's lat_deg and lon_deg, as an as-planted GeoJSON (RFC 7946) and as the run
// report's map in local metres. The place is as good as the fix (standalone: metres).
#include <string>
#include <vector>

#include "config/board_config.h"
#include "firmware/sensing/planting_monitor.h"
#include "planter/hal/gnss.h"
#include "sim/plant/seedling_process.h"

namespace planter::sim {

struct PlantedPlace {
  bool known = false;  // a fix on both sides within a second of the release
  double lat_deg = 0, lon_deg = 0;
  double east_m = 0, north_m = 0;  // from the first fix, on a local tangent plane
};

// One per released seedling (SeedlingProcess::seedlings() order, released ones).
std::vector<PlantedPlace> place_seedlings(const SeedlingProcess& seedlings,
                                          const std::vector<hal::GnssFix>& fixes,
                                          const config::GnssBoardConfig& antenna);

// The row as planted: a point a seedling (its x along the row, the gap before it, skip or
// multiple by the planting monitor's ratios of the target spacing, as its figures count them;
// damaged), and the receiver's
// track as a line.
std::string as_planted_geojson(const SeedlingProcess& seedlings,
                               const std::vector<PlantedPlace>& places,
                               const std::vector<hal::GnssFix>& fixes,
                               const PlantingMonitorConfig& monitor);

// The report's map: an SVG in local metres, one scale for both axes; skips and multiples marked.
std::string as_planted_svg(const SeedlingProcess& seedlings,
                           const std::vector<PlantedPlace>& places,
                           const PlantingMonitorConfig& monitor);

}  // namespace planter::sim
