#pragma once
// A recording the operator starts and stops from the console, beside planterd's own (which
// runs from start to stop): console-<UTC time>.csv in the recordings' directory, written the
// same crash-safe way from the same rows. The console's thread opens and closes it; the main
// thread adds the rows and flushes them; a mutex keeps the two apart (neither is the loop).
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "apps/planterd/crash_safe_recording.h"
#include "console/recording_control.h"

namespace planter::daemon {

class ConsoleRecording : public console::RecordingControl {
 public:
  ConsoleRecording(std::string dir, std::vector<std::string> metadata)
      : dir_(std::move(dir)), metadata_(std::move(metadata)) {}

  console::ConsoleReply start() override;
  console::ConsoleReply stop() override;
  std::string active() override {
    const std::lock_guard<std::mutex> lock(mutex_);
    return recording_ ? name_ : std::string();
  }
  // The main thread's side.
  void add(double t_s, const Telemetry& row);
  void flush();

 private:
  std::string dir_;
  std::vector<std::string> metadata_;
  std::mutex mutex_;
  std::unique_ptr<CrashSafeRecording> recording_;
  std::string name_;
  std::string failed_;  // a recording that stopped by itself (full disk), until stop() says it
};

}  // namespace planter::daemon
