#pragma once
// The commissioning tool against the simulated machine on the in-process bus.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <sstream>

#include "apps/planter-can/sim_link.h"
#include "apps/planter-can/tool_context.h"
#include "config/board_config.h"
#include "sim/runner/scenario.h"
#include "tests/board_copy.h"

namespace planter::cantool::test {

inline std::string source_path(const std::string& rel) {
  return std::string(PLANTER_SOURCE_DIR) + "/" + rel;
}

class CanToolTest : public ::testing::Test {
 protected:
  // A scratch copy of the host-sim board: calibrations write into its calibration file.
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("planter-can-test-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    board_path_ = planter::test::copy_board("host-sim", dir_).string();
    board_ = config::load_board(board_path_);
    scenario_.board = board_;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  void start(SimLinkOptions options = {}) {
    link_ = std::make_unique<SimLink>(scenario_, options);
    ctx_ = std::make_unique<ToolContext>(
        ToolContext{*link_, &board_, false, out_, err_, 100'000'000, false});
  }
  std::string out() { return out_.str(); }
  std::string err() { return err_.str(); }
  void clear() {
    out_.str("");
    err_.str("");
  }

  std::filesystem::path dir_;
  std::string board_path_;
  config::BoardConfig board_;
  sim::Scenario scenario_;
  std::unique_ptr<SimLink> link_;
  std::ostringstream out_, err_;
  std::unique_ptr<ToolContext> ctx_;
};

}  // namespace planter::cantool::test
