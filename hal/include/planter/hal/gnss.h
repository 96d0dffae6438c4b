#pragma once
// A GNSS receiver's fixes as the controller sees them: the speed over ground with the
// receiver's own error estimate, the fix's quality, its place and when it was valid. A board
// without a receiver passes none (ControllerHal::gnss is optional).
#include <atomic>
#include <cstdint>

namespace planter::hal {

// gpsd's fix modes (its TPV `mode`): 0 unknown, 1 no fix, 2 2D, 3 3D.
enum class GnssMode : std::uint8_t { kUnknown = 0, kNoFix = 1, k2D = 2, k3D = 3 };

struct GnssFix {
  std::uint64_t sequence = 0;  // counts fixes from 1; the same number is the same fix
  std::int64_t valid_ns = 0;   // when the fix was measured, on the controller's clock
  GnssMode mode = GnssMode::kUnknown;
  int satellites = 0;        // used in the fix (0: the receiver does not say)
  double hdop = 0;           // horizontal dilution of precision (0: not said)
  double speed_mps = 0;      // speed over ground
  double track_deg = 0;      // course over ground, degrees clockwise from true north
  double speed_err_mps = 0;  // the receiver's estimate of its speed error, 1 sigma (0: not said)
  double lat_deg = 0, lon_deg = 0;
  double receiver_time_s = 0;  // the receiver's own time of the fix, UNIX seconds (0: not said)
};

// A fix that places the antenna: 2D or 3D (gpsd's mode).
inline bool has_position(const GnssFix& f) {
  return f.mode == GnssMode::k2D || f.mode == GnssMode::k3D;
}

// Where the controller reads the newest fix, never blocking (the real-time loop).
class GnssSource {
 public:
  virtual ~GnssSource() = default;
  // The newest fix so far; false before the first. The same fix (sequence) may come again.
  virtual bool latest(GnssFix& fix) = 0;
  // The receiver's link (gpsd, or the simulated receiver) is up.
  [[nodiscard]] virtual bool connected() const = 0;
};

// One writer thread hands fixes to one reader without locks or allocation: a sequence lock
// (Lameter, "Effective synchronization on Linux/NUMA systems", 2005; the kernel's seqlock). The
// reader retries while a write is under way; the payload is copied word by word through
// relaxed atomics, so a torn read is never used and is not a data race.
class GnssMailbox {
 public:
  void put(const GnssFix& fix) {
    const std::uint64_t s = seq_.load(std::memory_order_relaxed);
    seq_.store(s + 1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_release);
    store(fix);
    seq_.store(s + 2, std::memory_order_release);
  }
  bool get(GnssFix& out) const {
    for (int tries = 0; tries < 64; ++tries) {
      const std::uint64_t s0 = seq_.load(std::memory_order_acquire);
      if (s0 == 0) return false;
      if (s0 & 1u) continue;
      load(out);
      std::atomic_thread_fence(std::memory_order_acquire);
      if (seq_.load(std::memory_order_relaxed) == s0) return true;
    }
    return false;  // a writer that never finishes: no fix this tick rather than a wait
  }

 private:
  static constexpr std::size_t kWords = (sizeof(GnssFix) + 7) / 8;
  void store(const GnssFix& fix) {
    std::uint64_t w[kWords]{};
    __builtin_memcpy(w, &fix, sizeof(fix));
    for (std::size_t i = 0; i < kWords; ++i) words_[i].store(w[i], std::memory_order_relaxed);
  }
  void load(GnssFix& fix) const {
    std::uint64_t w[kWords];
    for (std::size_t i = 0; i < kWords; ++i) w[i] = words_[i].load(std::memory_order_relaxed);
    __builtin_memcpy(&fix, w, sizeof(fix));
  }
  std::atomic<std::uint64_t> seq_{0};
  std::atomic<std::uint64_t> words_[kWords]{};
};

}  // namespace planter::hal
