#pragma once
// The console's recording commands, answered by the program that records (planter-sim live,
// planterd), from the server's thread: opening a file is no work for the control loop, and a
// file that cannot be opened is said to the operator at once.
#include <ctime>
#include <string>

#include "console/command_channel.h"

namespace planter::console {

// A recording's answer in the operator's words.
inline ConsoleReply recording_reply(ConsoleResult result, const std::string& words) {
  ConsoleReply reply;
  reply.result = result;
  reply.say(words.c_str());
  return reply;
}

// "<prefix>-20261124T223015Z.csv": the UTC time the operator started it, sortable by name.
inline std::string recording_file_name(const char* prefix) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &utc);
  return std::string(prefix) + "-" + stamp + ".csv";
}

class RecordingControl {
 public:
  virtual ~RecordingControl() = default;
  // Accepted with the file's name, refused (already recording, not recording), or failed
  // (the file cannot be written), in the operator's words.
  virtual ConsoleReply start() = 0;
  virtual ConsoleReply stop() = 0;
};

}  // namespace planter::console
