#pragma once
// planterd's as-planted map (config/as_planted.h): from the rows the loop hands the main
// thread, each seedling the photo-eye saw placed at the antenna's newest fix (at most a tick
// and the receiver's latency old: millimetres at planting speed) less the antenna's offset,
// and the fixes as the track. Written beside the recording at the end of the run.
#include <cstdint>
#include <string>
#include <vector>

#include "config/as_planted.h"
#include "config/board_config.h"
#include "firmware/controller/telemetry.h"

namespace planter::daemon {

class AsPlantedLog {
 public:
  explicit AsPlantedLog(const config::BoardConfig& board);
  void add(const Telemetry& row);
  [[nodiscard]] std::size_t placed() const { return seedlings_.size(); }
  [[nodiscard]] std::size_t unplaced() const { return unplaced_; }
  // The GeoJSON written whole (atomically) to `path`; false with `why` otherwise.
  bool write(const std::string& path, std::string& why) const;

 private:
  PlantingMonitorConfig monitor_;
  double ahead_m_, left_m_;
  std::uint64_t last_fix_ = 0;
  double seedlings_seen_ = 0, spacings_seen_ = 0;
  std::size_t unplaced_ = 0;  // seen with no fix in the last second
  std::vector<config::GeoPoint> track_;
  std::vector<config::PlantedSeedling> seedlings_;  // at the antenna until written
};

// The map's file beside a recording: "row.csv" gives "row.as_planted.geojson".
std::string as_planted_path(const std::string& recording);

}  // namespace planter::daemon
