#pragma once
// The person at the machine during a calibration. On real hardware the tool prints what to
// do and waits for Enter (or, for scripts, a fixed time); on `--iface sim` the simulated
// fixture does it (hangs the weight, pushes the machine).
#include <iosfwd>
#include <string>

#include "apps/planter-can/tool_link.h"

namespace planter::cantool {

enum class OperatorAction : unsigned char { kRemoveLoad, kHangWeight, kPushMachine, kNone };

class OperatorPrompt {
 public:
  // ready_after_s < 0: wait for Enter on stdin (fails without a terminal).
  OperatorPrompt(ToolLink& link, std::istream& in, std::ostream& err, double ready_after_s)
      : link_(link), in_(in), err_(err), ready_after_s_(ready_after_s) {}
  // False when nobody can do it (no terminal and no --ready-after-s).
  bool ask(const std::string& instruction, OperatorAction action, double value);

 private:
  ToolLink& link_;
  std::istream& in_;
  std::ostream& err_;
  double ready_after_s_;
};

}  // namespace planter::cantool
