#include "firmware/supervisor/supervisor.h"

#include <gtest/gtest.h>

using namespace planter;

TEST(Supervisor, NormalLifecycle) {
  Supervisor s;
  SupervisorInputs in;
  EXPECT_EQ(s.update(in), SupervisorState::kCommissioning);
  in.nodes_ready = true;
  EXPECT_EQ(s.update(in), SupervisorState::kReady);
  in.run_requested = true;
  EXPECT_EQ(s.update(in), SupervisorState::kRunning);
  in.run_requested = false;
  in.stop_requested = true;
  EXPECT_EQ(s.update(in), SupervisorState::kStopping);
  in.stop_requested = false;
  EXPECT_EQ(s.update(in), SupervisorState::kStopping);
  in.disc_stopped = true;
  EXPECT_EQ(s.update(in), SupervisorState::kReady);
}

TEST(Supervisor, FaultLatchesUntilResetWithCauseGone) {
  Supervisor s;
  SupervisorInputs in;
  in.nodes_ready = true;
  s.update(in);
  s.update(in);
  in.faults = fault::kHeartbeatLost;
  EXPECT_EQ(s.update(in), SupervisorState::kFault);
  EXPECT_EQ(s.latched_faults(), fault::kHeartbeatLost);
  in.reset_requested = true;
  EXPECT_EQ(s.update(in), SupervisorState::kFault);  // cause still there
  in.faults = 0;
  EXPECT_EQ(s.update(in), SupervisorState::kCommissioning);
}

TEST(Supervisor, EStopWinsFromAnyState) {
  Supervisor s;
  SupervisorInputs in;
  in.estop = true;
  EXPECT_EQ(s.update(in), SupervisorState::kEStop);
  in.estop = false;
  EXPECT_EQ(s.update(in), SupervisorState::kEStop);
  in.reset_requested = true;
  EXPECT_EQ(s.update(in), SupervisorState::kCommissioning);
}

TEST(Supervisor, BootFailureFaults) {
  Supervisor s;
  SupervisorInputs in;
  s.update(in);
  in.faults = fault::kBootFailed;
  EXPECT_EQ(s.update(in), SupervisorState::kFault);
}
