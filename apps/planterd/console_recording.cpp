#include "apps/planterd/console_recording.h"

#include <cstdio>
#include <ctime>
#include <stdexcept>

namespace planter::daemon {
namespace {
console::ConsoleReply answer(console::ConsoleResult result, const std::string& words) {
  console::ConsoleReply reply;
  reply.result = result;
  reply.say(words.c_str());
  return reply;
}
}  // namespace

console::ConsoleReply ConsoleRecording::start() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (recording_) return answer(console::ConsoleResult::kRefused, "already recording to " + name_);
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char name[64];
  std::strftime(name, sizeof name, "console-%Y%m%dT%H%M%SZ.csv", &utc);
  try {
    recording_ = std::make_unique<CrashSafeRecording>(dir_ + "/" + name, metadata_);
  } catch (const std::exception& e) {
    return answer(console::ConsoleResult::kFailed, e.what());
  }
  name_ = name;
  return answer(console::ConsoleResult::kAccepted, "recording to " + name_);
}

console::ConsoleReply ConsoleRecording::stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!recording_) return answer(console::ConsoleResult::kRefused, "not recording");
  const bool ok = recording_->flush();
  recording_.reset();
  if (!ok)
    return answer(console::ConsoleResult::kFailed,
                  name_ + ": the last rows cannot be written (is the disk full?)");
  return answer(console::ConsoleResult::kAccepted, "recording " + name_ + " closed");
}

void ConsoleRecording::add(double t_s, const Telemetry& row) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (recording_) (void)recording_->add(t_s, row);  // a row too long is planterd's to say
}

void ConsoleRecording::flush() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (recording_ && !recording_->flush()) {
    std::fprintf(stderr, "planterd: %s/%s: write failed; the console's recording stopped\n",
                 dir_.c_str(), name_.c_str());
    recording_.reset();
  }
}

}  // namespace planter::daemon
