#include "apps/planter-can/operator_prompt.h"

#include <unistd.h>

#include <istream>
#include <ostream>

namespace planter::cantool {

bool OperatorPrompt::ask(const std::string& instruction, OperatorAction action, double value) {
  err_ << ">> " << instruction << "\n";
  if (SimFixture* fx = link_.fixture()) {
    switch (action) {
      case OperatorAction::kRemoveLoad:
        fx->set_load_N(0.0);
        break;
      case OperatorAction::kHangWeight:
        fx->set_load_N(value);
        break;
      case OperatorAction::kPushMachine:
        fx->push_machine();
        break;
      case OperatorAction::kNone:
        break;
    }
    err_ << "   (sim fixture: done)\n";
    return true;
  }
  if (ready_after_s_ >= 0.0) {
    // Keep the bus drained while waiting.
    link_.idle_until(link_.now_ns() + static_cast<std::int64_t>(ready_after_s_ * 1e9));
    return true;
  }
  if (!isatty(STDIN_FILENO)) {
    err_ << "planter-can: this step needs a person: run it at a terminal or pass --ready-after-s\n";
    return false;
  }
  err_ << "   press Enter when done\n";
  std::string line;
  return static_cast<bool>(std::getline(in_, line));
}

}  // namespace planter::cantool
