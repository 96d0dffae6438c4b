#include "console/command_channel.h"

#include <optional>
#include <thread>

namespace planter::console {

namespace {
// Each console command once: its name on the wire, and the controller's command it is, if any.
struct Name {
  ConsoleCommandKind kind;
  const char* name;
  std::optional<CommandKind> command;  // none: the program's (the recording), not the loop's
};
constexpr Name kNames[] = {
    {ConsoleCommandKind::kRun, "run", CommandKind::kRun},
    {ConsoleCommandKind::kStop, "stop", CommandKind::kStop},
    {ConsoleCommandKind::kFaultReset, "fault_reset", CommandKind::kFaultReset},
    {ConsoleCommandKind::kSetDepth, "set_depth_mm", CommandKind::kSetDepth},
    {ConsoleCommandKind::kSetClampForce, "set_clamp_force_N", CommandKind::kSetClampForce},
    {ConsoleCommandKind::kRecordStart, "record_start", std::nullopt},
    {ConsoleCommandKind::kRecordStop, "record_stop", std::nullopt},
};
}  // namespace

bool controller_command(ConsoleCommandKind kind, OperatorCommand& out, double value) {
  for (const Name& n : kNames) {
    if (n.kind != kind) continue;
    if (!n.command) return false;
    out.kind = *n.command;
    out.value = value;
    return true;
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
