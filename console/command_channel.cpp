#include "console/command_channel.h"

#include <thread>

namespace planter::console {

namespace {
struct Name {
  ConsoleCommandKind kind;
  const char* name;
};
constexpr Name kNames[] = {
    {ConsoleCommandKind::kRun, "run"},
    {ConsoleCommandKind::kStop, "stop"},
    {ConsoleCommandKind::kFaultReset, "fault_reset"},
    {ConsoleCommandKind::kSetDepth, "set_depth_mm"},
    {ConsoleCommandKind::kSetClampForce, "set_clamp_force_N"},
    {ConsoleCommandKind::kRecordStart, "record_start"},
    {ConsoleCommandKind::kRecordStop, "record_stop"},
};
}  // namespace

bool controller_command(ConsoleCommandKind kind, OperatorCommand& out, double value) {
  out.value = value;
  switch (kind) {
    case ConsoleCommandKind::kRun:
      out.kind = CommandKind::kRun;
      return true;
    case ConsoleCommandKind::kStop:
      out.kind = CommandKind::kStop;
      return true;
    case ConsoleCommandKind::kFaultReset:
      out.kind = CommandKind::kFaultReset;
      return true;
    case ConsoleCommandKind::kSetDepth:
      out.kind = CommandKind::kSetDepth;
      return true;
    case ConsoleCommandKind::kSetClampForce:
      out.kind = CommandKind::kSetClampForce;
      return true;
    case ConsoleCommandKind::kRecordStart:
    case ConsoleCommandKind::kRecordStop:
      return false;
  }
  return false;
}

ConsoleResult console_result(CommandOutcome outcome) {
  switch (outcome) {
    case CommandOutcome::kAccepted:
      return ConsoleResult::kAccepted;
    case CommandOutcome::kOutOfRange:
      return ConsoleResult::kOutOfRange;
    case CommandOutcome::kRefusedEStop:
    case CommandOutcome::kRefusedFault:
    case CommandOutcome::kRefusedNotReady:
    case CommandOutcome::kRefusedGate:
      return ConsoleResult::kRefused;
  }
  return ConsoleResult::kRefused;
}

bool parse_command_name(const char* name, ConsoleCommandKind& kind) {
  for (const Name& n : kNames) {
    if (std::strcmp(n.name, name) == 0) {
      kind = n.kind;
      return true;
    }
  }
  return false;
}

const char* command_name(ConsoleCommandKind kind) {
  for (const Name& n : kNames)
    if (n.kind == kind) return n.name;
  return "unknown";
}

ConsoleReply CommandChannel::submit(ConsoleCommandKind kind, double value,
                                    std::chrono::milliseconds timeout) {
  std::lock_guard<std::mutex> lock(submit_mutex_);
  const std::uint64_t id = next_id_++;
  ConsoleReply reply;
  reply.id = id;
  // Answers to requests given up on earlier are dropped here.
  ConsoleReply stale;
  while (replies_.pop(stale)) {
  }
  if (!requests_.push(ConsoleRequest{id, kind, value})) {
    reply.say("the controller is busy: try again");
    return reply;
  }
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    ConsoleReply got;
    while (replies_.pop(got))
      if (got.id == id) return got;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  reply.say("the controller did not answer in time: the command may still take effect");
  return reply;
}

}  // namespace planter::console
