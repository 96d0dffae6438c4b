#include "firmware/canopen/cia402.h"

#include <gtest/gtest.h>

using namespace planter::canopen::cia402;

TEST(Cia402, StatuswordDecoding) {
  EXPECT_EQ(decode_state(0x0040), State::kSwitchOnDisabled);
  EXPECT_EQ(decode_state(0x0231), State::kReadyToSwitchOn);
  EXPECT_EQ(decode_state(0x0233), State::kSwitchedOn);
  EXPECT_EQ(decode_state(0x0637), State::kOperationEnabled);
  EXPECT_EQ(decode_state(0x0617), State::kQuickStopActive);
  EXPECT_EQ(decode_state(0x0218), State::kFault);
  for (State s : {State::kSwitchOnDisabled, State::kReadyToSwitchOn, State::kSwitchedOn,
                  State::kOperationEnabled, State::kQuickStopActive, State::kFault}) {
    EXPECT_EQ(decode_state(encode_state(s)), s) << state_name(s);
  }
}

// The master's controlwords walk the drive's state machine to operation enabled.
TEST(Cia402, MasterEnablesDrive) {
  State drive = State::kSwitchOnDisabled;
  std::uint16_t previous = 0;
  bool phase = false;
  int steps = 0;
  while (drive != State::kOperationEnabled && steps < 10) {
    const std::uint16_t cw = next_controlword(drive, State::kOperationEnabled, phase);
    drive = apply_controlword(drive, cw, previous);
    previous = cw;
    ++steps;
  }
  EXPECT_EQ(drive, State::kOperationEnabled);
  EXPECT_EQ(steps, 3);  // shutdown, switch on, enable
}

TEST(Cia402, QuickStopAndFaultReset) {
  bool phase = false;
  EXPECT_EQ(next_controlword(State::kOperationEnabled, State::kQuickStopActive, phase),
            controlword::kQuickStop);
  EXPECT_EQ(apply_controlword(State::kOperationEnabled, controlword::kQuickStop, 0x0F),
            State::kQuickStopActive);
  // Fault reset needs a rising edge of bit 7: the master alternates.
  State drive = State::kFault;
  std::uint16_t previous = controlword::kFaultReset;  // a held bit does not reset
  EXPECT_EQ(apply_controlword(drive, controlword::kFaultReset, previous), State::kFault);
  const std::uint16_t first = next_controlword(drive, State::kOperationEnabled, phase);
  drive = apply_controlword(drive, first, 0);
  if (drive == State::kFault) {
    const std::uint16_t second = next_controlword(drive, State::kOperationEnabled, phase);
    drive = apply_controlword(drive, second, first);
  }
  EXPECT_EQ(drive, State::kSwitchOnDisabled);
}
