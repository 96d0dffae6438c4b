// Operator commands (the console's, planterd's) never go around the supervisor: the e-stop, a
// fault and the commissioning gate each win, and a set-point outside the machine file's rule
// changes nothing. One test per rule, on the controller itself.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "firmware/controller/controller.h"
#include "firmware/controller/setpoint_rules.h"

using namespace planter;

namespace {

class OperatorCommands : public ::testing::Test {
 protected:
  OperatorCommands() : controller_(config()) {
    state_.nodes_started = true;
    state_.nodes_ready = true;
    state_.depth_mm = 0.0;
    tick(3);  // boot -> commissioning -> ready
  }
  static ControllerConfig config() {
    ControllerConfig c;
    c.depth.max_mm = 150.0;  // an actuator with less travel than the file's 160 mm
    return c;
  }
  void tick(int n = 1) {
    for (int i = 0; i < n; ++i) {
      t_ns_ += 10'000'000;
      controller_.update(state_, t_ns_, 10'000'000);
    }
  }
  CommandOutcome send(CommandKind kind, double value = 0.0) {
    const CommandOutcome o = controller_.command({kind, value});
    tick();
    return o;
  }
  double depth_target() const { return last().depth_target_mm; }
  double force_target() const { return last().clamp_force_target_N; }
  const MachineCommand& last() const { return last_; }
  void remember() { last_ = controller_.update(state_, t_ns_ += 10'000'000, 10'000'000); }

  Controller controller_;
  MachineState state_;
  MachineCommand last_;
  std::int64_t t_ns_ = 0;
};

TEST_F(OperatorCommands, ARunFromReadyIsTakenAndAStopIsAlwaysTaken) {
  ASSERT_EQ(controller_.state(), SupervisorState::kReady);
  EXPECT_EQ(send(CommandKind::kRun), CommandOutcome::kAccepted);
  EXPECT_EQ(controller_.state(), SupervisorState::kRunning);
  EXPECT_EQ(send(CommandKind::kStop), CommandOutcome::kAccepted);
  tick();  // stopping -> ready: the disc is at rest
  EXPECT_EQ(controller_.state(), SupervisorState::kReady);
}

TEST_F(OperatorCommands, ASetPointOutsideTheMachinesRuleChangesNothing) {
  remember();
  const double depth0 = depth_target(), force0 = force_target();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // The file's depth range is 40-160 mm; this actuator stops at 150 mm.
  for (double bad : {39.9, 150.1, 160.0, 1e9, -1.0, nan}) {
    EXPECT_EQ(send(CommandKind::kSetDepth, bad), CommandOutcome::kOutOfRange) << bad;
  }
  // The clamp force must stay below the ceiling (120 N, itself below the weakest seedling).
  for (double bad : {120.0, 127.2, -0.1, nan, std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(send(CommandKind::kSetClampForce, bad), CommandOutcome::kOutOfRange) << bad;
  }
  remember();
  EXPECT_EQ(depth_target(), depth0);
  EXPECT_EQ(force_target(), force0);
  EXPECT_EQ(send(CommandKind::kSetDepth, 150.0), CommandOutcome::kAccepted);
  EXPECT_EQ(send(CommandKind::kSetClampForce, 119.9), CommandOutcome::kAccepted);
  remember();
  EXPECT_EQ(depth_target(), 150.0);
  EXPECT_EQ(force_target(), 119.9);
}

TEST_F(OperatorCommands, TheRuleIsTheMachineFilesRule) {
  const ControllerConfig c = config();
  EXPECT_EQ(depth_range_mm(c).min, kDepthFileRangeMm.min);
  EXPECT_EQ(depth_range_mm(c).max, 150.0);
  EXPECT_TRUE(clamp_force_range_N(c).max_exclusive);
  EXPECT_EQ(clamp_force_range_N(c).max, c.clamp.ceiling_N);
}

TEST_F(OperatorCommands, TheEStopWinsOverEveryCommandButStop) {
  ASSERT_EQ(send(CommandKind::kRun), CommandOutcome::kAccepted);
  state_.estop = true;
  tick();
  ASSERT_EQ(controller_.state(), SupervisorState::kEStop);
  remember();
  const double depth0 = depth_target(), force0 = force_target();
  EXPECT_EQ(send(CommandKind::kRun), CommandOutcome::kRefusedEStop);
  EXPECT_EQ(send(CommandKind::kFaultReset), CommandOutcome::kRefusedEStop);
  EXPECT_EQ(send(CommandKind::kSetDepth, 120.0), CommandOutcome::kRefusedEStop);
  EXPECT_EQ(send(CommandKind::kSetClampForce, 80.0), CommandOutcome::kRefusedEStop);
  EXPECT_EQ(send(CommandKind::kStop), CommandOutcome::kAccepted);
  remember();
  EXPECT_EQ(controller_.state(), SupervisorState::kEStop);
  EXPECT_FALSE(last().drives_enabled);
  EXPECT_EQ(depth_target(), depth0);
  EXPECT_EQ(force_target(), force0);
  // Released: a reset is taken, and the machine boots its nodes again before it can run.
  state_.estop = false;
  tick();
  EXPECT_EQ(send(CommandKind::kFaultReset), CommandOutcome::kAccepted);
  EXPECT_NE(controller_.state(), SupervisorState::kEStop);
}

TEST_F(OperatorCommands, AFaultWinsOverRunAndSetPoints) {
  ASSERT_EQ(send(CommandKind::kRun), CommandOutcome::kAccepted);
  state_.link_faults = fault::kHeartbeatLost;
  tick();
  ASSERT_EQ(controller_.state(), SupervisorState::kFault);
  EXPECT_EQ(send(CommandKind::kRun), CommandOutcome::kRefusedFault);
  EXPECT_EQ(send(CommandKind::kSetDepth, 120.0), CommandOutcome::kRefusedFault);
  EXPECT_EQ(send(CommandKind::kSetClampForce, 80.0), CommandOutcome::kRefusedFault);
  EXPECT_EQ(controller_.state(), SupervisorState::kFault);
  // A reset while the cause holds is taken but cannot clear it: the supervisor decides.
  EXPECT_EQ(send(CommandKind::kFaultReset), CommandOutcome::kAccepted);
  EXPECT_EQ(controller_.state(), SupervisorState::kFault);
}

TEST_F(OperatorCommands, TheCommissioningGateWinsOverRun) {
  controller_.set_run_gate(false);
  EXPECT_EQ(send(CommandKind::kRun), CommandOutcome::kRefusedGate);
  EXPECT_EQ(controller_.state(), SupervisorState::kReady);
  // Set-points may be prepared while the gate is closed: they move nothing.
  EXPECT_EQ(send(CommandKind::kSetDepth, 90.0), CommandOutcome::kAccepted);
  controller_.set_run_gate(true);
  EXPECT_EQ(send(CommandKind::kRun), CommandOutcome::kAccepted);
  EXPECT_EQ(controller_.state(), SupervisorState::kRunning);
}

TEST_F(OperatorCommands, ARunWhileTheNodesBootIsRefused) {
  Controller fresh(config());
  MachineState booting;  // nodes not ready
  fresh.update(booting, 10'000'000, 10'000'000);
  fresh.update(booting, 20'000'000, 10'000'000);
  ASSERT_EQ(fresh.state(), SupervisorState::kCommissioning);
  EXPECT_EQ(fresh.command({CommandKind::kRun, 0.0}), CommandOutcome::kRefusedNotReady);
}

}  // namespace
