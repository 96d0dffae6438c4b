#pragma once
// The console's recording commands, answered by the program that records (planter-sim live,
// planterd), from the server's thread: opening a file is no work for the control loop, and a
// file that cannot be opened is said to the operator at once.
#include <atomic>
#include <cstdio>
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

// "<prefix>-20261124T223015.123Z-1.csv": the UTC time the operator started it to the
// millisecond, and how many this program has started, so two starts within a second never
// share a name (issue 28, item 7); sortable by name. The writers also create it exclusively.
inline std::string recording_file_name(const char* prefix) {
  static std::atomic<unsigned> started{0};
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  std::tm utc{};
  gmtime_r(&now.tv_sec, &utc);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%S", &utc);
  char rest[48];
  std::snprintf(rest, sizeof rest, ".%03ldZ-%u.csv", now.tv_nsec / 1'000'000, ++started);
  return std::string(prefix) + "-" + stamp + rest;
}

// A recording whose writes failed (a full disk) is cut: it is renamed NAME.csv.cut, so the
// console no longer offers it as a recording, and the words say so. Returns the words.
inline std::string set_aside_cut(const std::string& dir, const std::string& name,
                                 const std::string& why) {
  const std::string from = dir + "/" + name, to = from + ".cut";
  const bool moved = std::rename(from.c_str(), to.c_str()) == 0;
  return "recording " + name + " stopped: " + why +
         (moved ? "; what was written is kept as " + name + ".cut"
                : "; the cut file could not be renamed: " + from);
}

class RecordingControl {
 public:
  virtual ~RecordingControl() = default;
  // Accepted with the file's name, refused (already recording, not recording), or failed
  // (the file cannot be written), in the operator's words.
  virtual ConsoleReply start() = 0;
  virtual ConsoleReply stop() = 0;
  // The file being recorded to, "" when none: the page's recording indicator.
  virtual std::string active() = 0;
};

}  // namespace planter::console
