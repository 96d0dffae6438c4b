#pragma once
// The console's recording commands, answered by the program that records (planter-sim live,
// planterd), from the server's thread: opening a file is no work for the control loop, and a
// file that cannot be opened is said to the operator at once.
#include "console/command_channel.h"

namespace planter::console {

class RecordingControl {
 public:
  virtual ~RecordingControl() = default;
  // Accepted with the file's name, refused (already recording, not recording), or failed
  // (the file cannot be written), in the operator's words.
  virtual ConsoleReply start() = 0;
  virtual ConsoleReply stop() = 0;
};

}  // namespace planter::console
