#include "sim/runner/recording_thread.h"

namespace planter::sim {

RecordingThread::RecordingThread(RecordingWriter& writer) : writer_(writer) {
  filling_.reserve(kBatchRows);
  writing_.reserve(kBatchRows);
  thread_ = std::thread([this] { run(); });
}

RecordingThread::~RecordingThread() { stop(); }

void RecordingThread::stop() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  cv_.notify_all();
  // The thread writes a batch handed over before it sees stopping_ (its wait prefers the batch).
  if (thread_.joinable()) thread_.join();
}

void RecordingThread::write(const TickRecord& row) {
  filling_.push_back({row.controller, row.truth});
  if (filling_.size() == kBatchRows) hand_over();
}

void RecordingThread::hand_over() {
  std::unique_lock<std::mutex> lock(mutex_);
  cv_.wait(lock, [this] { return !batch_ready_; });  // the writer took the last batch
  filling_.swap(writing_);
  filling_.clear();
  batch_ready_ = true;
  lock.unlock();
  cv_.notify_all();
}

void RecordingThread::run() {
  std::vector<Row> batch;
  batch.reserve(kBatchRows);
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      cv_.wait(lock, [this] { return batch_ready_ || stopping_; });
      if (!batch_ready_) return;
      batch.swap(writing_);
      batch_ready_ = false;
    }
    cv_.notify_all();
    // After a failed write the rest is not written: close() throws the first failure.
    if (!failed_) {
      try {
        for (const Row& r : batch) writer_.write({r.controller, r.truth});
      } catch (...) {
        failed_ = std::current_exception();
      }
    }
    batch.clear();
  }
}

void RecordingThread::close() {
  if (!filling_.empty()) hand_over();
  stop();
  if (failed_) std::rethrow_exception(failed_);
  writer_.close();
}

}  // namespace planter::sim
