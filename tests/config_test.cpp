#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "config/board_config.h"
#include "config/config_error.h"
#include "sim/runner/scenario.h"

using namespace planter;

namespace {
const std::string kBoard = std::string(PLANTER_SOURCE_DIR) + "/boards/host-sim/board.toml";

// A copy of the real board file with one line replaced (or appended).
std::string board_with(const std::string& pattern, const std::string& replacement) {
  std::ifstream in(kBoard);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  text = pattern.empty() ? text + replacement
                         : std::regex_replace(text, std::regex(pattern), replacement);
  const auto path =
      std::filesystem::temp_directory_path() /
      ("planter-board-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
       std::to_string(std::hash<std::string>{}(pattern + replacement)) + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

std::string error_of(const std::string& path) {
  try {
    planter::config::load_board(path);
  } catch (const planter::config::ConfigError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(BoardConfig, LoadsTheHostSimBoard) {
  const auto b = planter::config::load_board(kBoard);
  EXPECT_EQ(b.name, "host-sim");
  EXPECT_EQ(b.controller.node(NodeRole::kDiscDrive).node_id, 2);
  EXPECT_EQ(b.controller.node(NodeRole::kForceSensor).profile, 404);
  EXPECT_EQ(b.controller.node(NodeRole::kDepthActuator).tpdo[0].count, 3);
  EXPECT_DOUBLE_EQ(b.controller.clamp.ceiling_N, 120.0);
}

TEST(BoardConfig, UnknownKeyNamesFileLineAndKey) {
  const auto path = board_with("", "\n[disc]\n");  // duplicate table: a parse error with a line
  EXPECT_NE(error_of(path).find(path + ":"), std::string::npos);
  const auto typo =
      board_with("clamp_force_N = 90.0", "clamp_force_N = 90.0\nclamp_forse_N = 80.0");
  const std::string e = error_of(typo);
  EXPECT_NE(e.find("'control.clamp_forse_N': unknown key"), std::string::npos) << e;
  // The typo sits on the line after clamp_force_N in the real file.
  std::ifstream in(kBoard);
  std::string line;
  int n = 0;
  while (std::getline(in, line) && line.rfind("clamp_force_N", 0) != 0) ++n;
  std::string needle = ":";
  needle += std::to_string(n + 2);
  needle += ':';
  EXPECT_NE(e.find(needle), std::string::npos) << e;
}

TEST(BoardConfig, WrongTypeAndRange) {
  EXPECT_NE(error_of(board_with("depth_mm = 102.0", "depth_mm = \"deep\""))
                .find("'control.depth_mm': must be a number"),
            std::string::npos);
  const std::string e = error_of(board_with("depth_mm = 102.0", "depth_mm = 300.0"));
  EXPECT_NE(e.find("300 is out of range; allowed [40, 160] mm"), std::string::npos) << e;
}

TEST(BoardConfig, CeilingAboveDamageThresholdIsRefused) {
  const std::string e = error_of(board_with("clamp_ceiling_N = 120.0", "clamp_ceiling_N = 150.0"));
  EXPECT_NE(e.find("'control.clamp_ceiling_N'"), std::string::npos) << e;
  EXPECT_NE(e.find("damage threshold"), std::string::npos) << e;
}

TEST(BoardConfig, DuplicateNodeIdAndBadPdoEntry) {
  EXPECT_NE(error_of(board_with("id = 3", "id = 2")).find("is used by another node"),
            std::string::npos);
  const std::string e = error_of(board_with("\"7130:01:16\"", "\"7130:01:12\""));
  EXPECT_NE(e.find("nodes.force_sensor.tpdo1"), std::string::npos) << e;
}

TEST(BoardConfig, MissingFile) {
  EXPECT_NE(error_of("/nonexistent/board.toml").find("no such file"), std::string::npos);
}

TEST(ScenarioConfig, FieldScenarioLoads) {
  const auto s =
      sim::load_scenario(std::string(PLANTER_SOURCE_DIR) + "/scenarios/zhangqiu-field.toml");
  EXPECT_EQ(s.name, "zhangqiu-field");
  EXPECT_DOUBLE_EQ(s.plant.route.distance_m, 30.0);
  ASSERT_EQ(s.plant.route.stops.size(), 1u);
  EXPECT_DOUBLE_EQ(s.plant.effects.disc_coulomb_Nm, 0.0);  // effects are off by default
}

// Values inside their ranges whose arithmetic is wrong: refused with the key and the limit.
TEST(BoardConfig, ScalingThatWrapsOrRoundsToZeroIsRefused) {
  const std::string wraps =
      error_of(board_with("counts_per_unit = 32595.0", "counts_per_unit = 1e9"));
  EXPECT_NE(wraps.find("'nodes.disc_drive.counts_per_unit': 1e+09 makes the disc"),
            std::string::npos)
      << wraps;
  EXPECT_NE(wraps.find("32-bit object"), std::string::npos) << wraps;
  const std::string coarse =
      error_of(board_with("counts_per_unit = 32595.0", "counts_per_unit = 1e-6"));
  EXPECT_NE(coarse.find("makes one count 1e+06 rad/s of disc speed"), std::string::npos) << coarse;
  EXPECT_EQ(error_of(kBoard), "");
}

TEST(BoardConfig, BusLoadOverTheBitRateIsRefusedAndOverHalfWarned) {
  // 10 kbit/s with a 1 ms SYNC: the board, which "planted normally" at 9576 %.
  const std::string e = error_of(
      board_with("bitrate = 500000\nsync_period_ms = 10", "bitrate = 10000\nsync_period_ms = 1"));
  EXPECT_NE(e.find("'can.bitrate': the board's SYNC, PDOs and heartbeats need"), std::string::npos)
      << e;
  EXPECT_NE(e.find("at most 100 %"), std::string::npos) << e;
  const auto b = planter::config::load_board(kBoard);
  EXPECT_GT(b.planned_bus_load_pct, 10.0);
  EXPECT_LT(b.planned_bus_load_pct, 30.0);
  EXPECT_TRUE(b.warnings.empty());
  const auto busy = planter::config::load_board(board_with("bitrate = 500000", "bitrate = 125000"));
  EXPECT_GT(busy.planned_bus_load_pct, 50.0);
  ASSERT_EQ(busy.warnings.size(), 1u);
  EXPECT_NE(busy.warnings[0].find("over the 50 % guideline"), std::string::npos);
}
