#pragma once
// Commands from the console's threads to the loop, and the loop's answers, through two bounded
// lock-free queues: the loop never waits, locks or allocates for them. The server's threads
// take one mutex among themselves (commands are rare and rate-limited), push a request, and
// wait up to a timeout for the answer with the same id.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <mutex>

#include "console/spsc_queue.h"
#include "firmware/controller/operator_command.h"

namespace planter::console {

// What the console may ask: the controller's commands, and the recording (the program's own).
enum class ConsoleCommandKind : std::uint8_t {
  kRun,
  kStop,
  kFaultReset,
  kSetDepth,
  kSetClampForce,
  kRecordStart,
  kRecordStop,
};

struct ConsoleRequest {
  std::uint64_t id = 0;
  ConsoleCommandKind kind = ConsoleCommandKind::kStop;
  double value = 0.0;
};

enum class ConsoleResult : std::uint8_t {
  kAccepted,
  kOutOfRange,  // nothing changed
  kRefused,     // the supervisor (e-stop, fault, gate, not ready) or the program refused it
  kFailed,      // it was tried and did not work (a recording that cannot be written)
  kNoAnswer,    // the loop did not answer in time
};

struct ConsoleReply {
  std::uint64_t id = 0;
  ConsoleResult result = ConsoleResult::kNoAnswer;
  double t_s = 0.0;     // the machine's time when the loop handled it
  char text[160] = {};  // the operator's words; fixed size, so the loop need not allocate
  void say(const char* words) {
    std::strncpy(text, words, sizeof text - 1);
    text[sizeof text - 1] = '\0';
  }
};

// The controller's commands as the console names them, and back; false for the recording's.
bool controller_command(ConsoleCommandKind kind, OperatorCommand& out, double value);
ConsoleResult console_result(CommandOutcome outcome);
// "run", "stop", "fault_reset", "set_depth_mm", "set_clamp_force_N", "record_start",
// "record_stop"; false for any other name.
bool parse_command_name(const char* name, ConsoleCommandKind& kind);
const char* command_name(ConsoleCommandKind kind);
[[nodiscard]] inline bool takes_value(ConsoleCommandKind k) {
  return k == ConsoleCommandKind::kSetDepth || k == ConsoleCommandKind::kSetClampForce;
}

// The loop's answer to a request: the controller (a ControlCycle) decides. A request that is
// not the controller's is refused, never taken for another command.
template <typename Controller>
void answer_with(Controller& controller, const ConsoleRequest& request, ConsoleReply& reply) {
  OperatorCommand c;
  if (!controller_command(request.kind, c, request.value)) {
    reply.result = ConsoleResult::kRefused;
    reply.say("refused: not a command for the controller");
    return;
  }
  const CommandOutcome outcome = controller.command(c);
  reply.result = console_result(outcome);
  reply.say(command_outcome_text(outcome));
}

class CommandChannel {
 public:
  explicit CommandChannel(std::size_t capacity = 16) : requests_(capacity), replies_(capacity) {}

  // The server's side: the answer, or kNoAnswer after `timeout`.
  ConsoleReply submit(ConsoleCommandKind kind, double value, std::chrono::milliseconds timeout);

  // The loop's side, once a tick: answers every waiting request with handle(request, reply).
  template <typename Handle>
  void serve(Handle&& handle) {
    ConsoleRequest request;
    while (requests_.pop(request)) {
      ConsoleReply reply;
      reply.id = request.id;
      handle(request, reply);
      replies_.push(reply);  // full only if the server gave up on many: then it is not waiting
    }
  }

 private:
  SpscQueue<ConsoleRequest> requests_;
  SpscQueue<ConsoleReply> replies_;
  std::mutex submit_mutex_;  // the server's threads, one command at a time
  std::uint64_t next_id_ = 1;
};

}  // namespace planter::console
