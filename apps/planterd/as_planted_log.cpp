#include "apps/planterd/as_planted_log.h"

#include <algorithm>
#include <cmath>

#include "config/durable_file.h"

namespace planter::daemon {

AsPlantedLog::AsPlantedLog(const config::BoardConfig& board)
    : monitor_(board.controller.monitor),
      ahead_m_(board.gnss.antenna_ahead_m),
      left_m_(board.gnss.antenna_left_m) {}

void AsPlantedLog::add(const Telemetry& row) {
  const bool placed = row.lat_deg != 0.0 || row.lon_deg != 0.0;  // the recording's "no place"
  if (placed && row.gnss.sequence != last_fix_) {
    last_fix_ = row.gnss.sequence;
    track_.push_back({row.lat_deg, row.lon_deg});
  }
  const double seen = row.planting.seedlings;
  const bool spaced = row.planting.spacings > spacings_seen_;
  spacings_seen_ = row.planting.spacings;
  const auto fresh = static_cast<std::uint32_t>(std::max(0.0, seen - seedlings_seen_));
  for (std::uint32_t i = 0; i < fresh; ++i) {
    if (!placed) {
      ++unplaced_;
      continue;
    }
    config::PlantedSeedling s;
    s.number = static_cast<int>(seedlings_seen_) + 1 + static_cast<int>(i);
    s.place = {row.lat_deg, row.lon_deg};  // the antenna's, until write() moves it back
    // The wheel's distance at the eye; unknown for seedlings of rows the queue dropped.
    const bool at_known =
        fresh == row.seedlings_this_tick && i < MachineState::kMaxSeedlingsPerTick;
    s.x_m = at_known ? row.seedling_at_m[i] : std::nan("");
    // Two in a tick (a double at the eye): only the last one's spacing is the monitor's.
    s.spacing_mm = i + 1 == fresh && spaced ? row.planting.spacing_mm : std::nan("");
    s.damaged = std::nullopt;  // the clamp sees a collapse in the disc, not which seedling lands
    s.tilt_deg = std::nan("");
    seedlings_.push_back(s);
  }
  seedlings_seen_ = seen;
}

bool AsPlantedLog::write(const std::string& path, std::string& why) const {
  const config::AntennaOffset offset(track_, ahead_m_, left_m_);
  std::vector<config::PlantedSeedling> released = seedlings_;
  for (config::PlantedSeedling& s : released) s.place = offset.release_point(s.place);
  return config::write_file_atomic(path, config::as_planted_geojson(track_, released, monitor_),
                                   &why);
}

std::string as_planted_path(const std::string& recording) {
  const std::string csv = ".csv";
  const bool ends_csv = recording.size() > csv.size() &&
                        recording.compare(recording.size() - csv.size(), csv.size(), csv) == 0;
  return (ends_csv ? recording.substr(0, recording.size() - csv.size()) : recording) +
         ".as_planted.geojson";
}

}  // namespace planter::daemon
