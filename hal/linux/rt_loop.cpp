#include "hal/linux/rt_loop.h"

#include <errno.h>
#include <fcntl.h>
#include <malloc.h>
#include <sched.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

#include "hal/linux/hal_error.h"

namespace planter::hal::linux_backend {
namespace {

// Touch every page of a stack region so later calls never page-fault in the loop.
[[gnu::noinline]] void prefault_stack(std::size_t bytes) {
  volatile unsigned char* region = static_cast<volatile unsigned char*>(__builtin_alloca(bytes));
  for (std::size_t i = 0; i < bytes; i += 4096) region[i] = 0;
}

}  // namespace

void LatencyHistogram::add(std::int64_t latency_ns) {
  if (latency_ns < 0) latency_ns = 0;
  const std::size_t bin = static_cast<std::size_t>(latency_ns / 1000);
  ++bins_[bin < kBins ? bin : kBins - 1];
  ++count_;
  sum_ns_ += static_cast<double>(latency_ns);
  if (latency_ns > max_ns_) max_ns_ = latency_ns;
}

double LatencyHistogram::percentile_us(double p) const {
  if (count_ == 0) return 0.0;
  const double target = p / 100.0 * static_cast<double>(count_);
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < kBins; ++i) {
    seen += bins_[i];
    if (static_cast<double>(seen) >= target) return static_cast<double>(i) + 1.0;  // bin's top
  }
  return static_cast<double>(kBins);
}

double LatencyHistogram::mean_us() const {
  return count_ == 0 ? 0.0 : sum_ns_ / static_cast<double>(count_) * 1e-3;
}

RtLoop::~RtLoop() {
  if (dma_latency_fd_ >= 0) close(dma_latency_fd_);
}

std::string RtLoop::setup() {
  std::string refused;
  auto refuse = [&](const std::string& what) {
    if (config_.require_realtime) throw HalError("realtime: " + what);
    refused += (refused.empty() ? "" : "; ") + what;
  };
  if (config_.cpu >= 0) {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(config_.cpu, &set);
    if (sched_setaffinity(0, sizeof set, &set) != 0)
      refuse("cannot pin to CPU " + std::to_string(config_.cpu) + ": " + std::strerror(errno));
  }
  // Keep the CPUs out of deep idle states for as long as the loop runs (as cyclictest does):
  // waking from them costs more than the whole control computation.
  if (dma_latency_fd_ < 0) {
    dma_latency_fd_ = open("/dev/cpu_dma_latency", O_WRONLY | O_CLOEXEC);
    const std::int32_t zero = 0;
    if (dma_latency_fd_ < 0 || write(dma_latency_fd_, &zero, sizeof zero) != sizeof zero)
      refuse(std::string("cannot hold /dev/cpu_dma_latency at 0: ") + std::strerror(errno));
  }
  if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0)
    refuse(std::string("mlockall refused: ") + std::strerror(errno));
  // Keep freed heap memory mapped and never serve malloc from fresh mmap()s.
  mallopt(M_TRIM_THRESHOLD, -1);
  mallopt(M_MMAP_MAX, 0);
  if (config_.prefault_heap_bytes > 0) {
    auto* heap = static_cast<unsigned char*>(std::malloc(config_.prefault_heap_bytes));
    if (heap != nullptr) {
      for (std::size_t i = 0; i < config_.prefault_heap_bytes; i += 4096) heap[i] = 1;
      std::free(heap);
    }
  }
  if (config_.prefault_stack_bytes > 0) prefault_stack(config_.prefault_stack_bytes);
  if (config_.priority > 0) {
    sched_param param{};
    param.sched_priority = config_.priority;
    if (sched_setscheduler(0, SCHED_FIFO, &param) != 0)
      refuse("SCHED_FIFO priority " + std::to_string(config_.priority) +
             " refused: " + std::strerror(errno));
  }
  return refused;
}

}  // namespace planter::hal::linux_backend
