// planterd's as-planted map (apps/planterd/as_planted_log.h) fed rows as the loop hands them:
// each seedling the photo-eye saw at the antenna's fix less its offset, the spacing the
// monitor counted, and a seedling seen with no fix counted but not placed.
#include "apps/planterd/as_planted_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "config/input_file.h"
#include "config/local_plane.h"

namespace planter::daemon {
namespace {

TEST(AsPlantedLog, PlacesEachSeedlingAtTheFixLessTheAntennaOffset) {
  config::BoardConfig board;
  board.gnss.antenna_ahead_m = 0.5;
  board.controller.monitor.target_spacing_mm = 30.0;
  AsPlantedLog log(board);
  const config::LocalPlane plane{36.7, 117.5};
  Telemetry row;
  // Northward at 0.06 m/s, a fix every 10 ticks, a seedling every 50 (30 mm), the fix lost
  // from 3 m to 3.3 m.
  for (int tick = 0; tick < 6000; ++tick) {
    const double north_m = 0.0006 * tick;
    const bool fix = tick < 5000 || tick >= 5500;
    if (tick % 10 == 0) {
      row.gnss.sequence += 1;
      plane.to_geo(0.0, north_m, row.lat_deg, row.lon_deg);
    }
    if (!fix) row.lat_deg = row.lon_deg = 0.0;
    row.seedlings_this_tick = tick % 50 == 0 ? 1 : 0;
    if (row.seedlings_this_tick == 1) {
      row.seedling_at_m[0] = north_m;
      if (row.planting.seedlings > 0) {
        row.planting.spacings += 1;
        row.planting.spacing_mm = 30.0;
      }
      row.planting.seedlings += 1;
    }
    log.add(row);
  }
  EXPECT_EQ(log.placed() + log.unplaced(), 120u);
  EXPECT_EQ(log.unplaced(), 10u) << "0.3 m without a fix: ten seedlings seen, not placed";
  const auto dir = std::filesystem::temp_directory_path() / "as_planted_log_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "row.as_planted.geojson").string();
  std::string why;
  ASSERT_TRUE(log.write(path, why)) << why;
  const auto geo = nlohmann::json::parse(config::read_input_file(path));
  std::filesystem::remove_all(dir);
  const auto& f = geo["features"];
  ASSERT_EQ(f.size(), 1 + log.placed());
  EXPECT_EQ(f[0]["geometry"]["type"], "LineString");
  const auto& second = f[2];
  EXPECT_EQ(second["properties"]["seedling"], 2);
  EXPECT_DOUBLE_EQ(second["properties"]["spacing_mm"].get<double>(), 30.0);
  EXPECT_TRUE(second["properties"]["damaged"].is_null());
  double east = 0, north = 0;
  plane.to_local(second["geometry"]["coordinates"][1].get<double>(),
                 second["geometry"]["coordinates"][0].get<double>(), east, north);
  // The antenna's fix at the seedling (0.03 m up the row) less 0.5 m ahead: 0.47 m behind it.
  EXPECT_NEAR(north, 0.03 - 0.5, 1e-6);
  EXPECT_NEAR(east, 0.0, 1e-6);
}

TEST(AsPlantedLog, BesideTheRecording) {
  EXPECT_EQ(as_planted_path("/var/lib/planterd/row.csv"),
            "/var/lib/planterd/row.as_planted.geojson");
  EXPECT_EQ(as_planted_path("row"), "row.as_planted.geojson");
}

}  // namespace
}  // namespace planter::daemon
