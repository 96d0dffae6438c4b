#pragma once
// The recording written off the simulation's thread: `planter-sim run` spends about a tenth of
// its time formatting rows (issue 30). The simulation copies each tick's telemetry and truth
// into a batch; a full batch is handed to a writer thread that formats and writes it while the
// next one fills. The file is the same, row for row: one writer, in order. A write that fails
// is kept and thrown by close(), on the caller's thread.
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "sim/runner/recording_writer.h"

namespace planter::sim {

class RecordingThread {
 public:
  explicit RecordingThread(RecordingWriter& writer);
  ~RecordingThread();  // stops the thread; what close() was not called for is dropped
  RecordingThread(const RecordingThread&) = delete;
  RecordingThread& operator=(const RecordingThread&) = delete;
  void write(const TickRecord& row);
  // Writes what is left, stops the thread, closes the writer; throws what any write threw.
  void close();

 private:
  struct Row {
    Telemetry controller;
    PlantTruth truth;
  };
  static constexpr std::size_t kBatchRows = 1024;
  void run();
  void hand_over();  // the filled batch to the writer, once it has finished the last one
  void stop();       // the thread told to stop, and joined

  RecordingWriter& writer_;
  std::vector<Row> filling_, writing_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool batch_ready_ = false, stopping_ = false;
  std::exception_ptr failed_;
  std::thread thread_;
};

}  // namespace planter::sim
