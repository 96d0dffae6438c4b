#include "apps/planterd/console_recording.h"

#include <cstdio>
#include <stdexcept>

namespace planter::daemon {
using console::ConsoleResult;
using console::recording_reply;

console::ConsoleReply ConsoleRecording::start() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (recording_) return recording_reply(ConsoleResult::kRefused, "already recording to " + name_);
  const std::string name = console::recording_file_name("console");
  try {
    recording_ = std::make_unique<CrashSafeRecording>(dir_ + "/" + name, metadata_);
  } catch (const std::exception& e) {
    return recording_reply(ConsoleResult::kFailed, e.what());
  }
  name_ = name;
  failed_.clear();
  return recording_reply(ConsoleResult::kAccepted, "recording to " + name_);
}

console::ConsoleReply ConsoleRecording::stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!recording_ && !failed_.empty()) {  // it stopped by itself: say why, once
    const std::string words = failed_;
    failed_.clear();
    return recording_reply(ConsoleResult::kFailed, words);
  }
  if (!recording_) return recording_reply(ConsoleResult::kRefused, "not recording");
  const bool ok = recording_->flush();
  recording_.reset();
  if (!ok)
    return recording_reply(
        ConsoleResult::kFailed,
        console::set_aside_cut(dir_, name_, "the last rows cannot be written (is the disk full?)"));
  return recording_reply(ConsoleResult::kAccepted, "recording " + name_ + " closed");
}

void ConsoleRecording::add(double t_s, const Telemetry& row) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (recording_) (void)recording_->add(t_s, row);  // a row too long is planterd's to say
}

void ConsoleRecording::flush() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (recording_ && !recording_->flush()) {
    recording_.reset();
    failed_ = console::set_aside_cut(dir_, name_, "cannot be written (is the disk full?)");
    std::fprintf(stderr, "planterd: the console's %s\n", failed_.c_str());
  }
}

}  // namespace planter::daemon
