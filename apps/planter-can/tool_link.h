#pragma once
// The bus as the commissioning tool sees it: a CanBus that can also wait for the next frame
// (a real socket blocks in epoll; the simulated machine advances its own clock), a clock,
// the soil-wheel encoder lines when the tool can read them, and a tap that sees every frame
// sent and received (the recorder). Sends are paced: a full transmit queue is retried for a
// bounded time instead of dropping the frame (127 back-to-back SDO requests overflow it).
#include <cstdint>
#include <iosfwd>
#include <string>

#include "planter/hal/can_bus.h"
#include "planter/hal/gpio.h"

namespace planter::cantool {

class FrameTap {
 public:
  virtual ~FrameTap() = default;
  // time_ns: CLOCK_REALTIME-like wall time for logs (the sim's epoch is 0).
  virtual void on_frame(std::int64_t time_ns, const hal::CanFrame& frame, bool transmitted) = 0;
};

// What the simulated machine lets a calibration do by hand (hang a weight, push the machine).
class SimFixture {
 public:
  virtual ~SimFixture() = default;
  virtual void set_load_N(double load_N) = 0;
  virtual void push_machine() = 0;  // rolls the machine over the sim's calibration distance
};

// candump -L lines into a stream (frames the tool sends are logged like the rest: the log has
// no direction column).
class LogWriter final : public FrameTap {
 public:
  LogWriter(std::ostream& out, std::string interface)
      : out_(out), interface_(std::move(interface)) {}
  void on_frame(std::int64_t time_ns, const hal::CanFrame& frame, bool transmitted) override;
  [[nodiscard]] std::uint64_t frames() const { return frames_; }

 private:
  std::ostream& out_;
  std::string interface_;
  std::uint64_t frames_ = 0;
};

// Two taps at once (a `record` inside a session that is logged as a whole).
class TapPair final : public FrameTap {
 public:
  TapPair(FrameTap& first, FrameTap* second) : first_(first), second_(second) {}
  void on_frame(std::int64_t time_ns, const hal::CanFrame& frame, bool transmitted) override {
    first_.on_frame(time_ns, frame, transmitted);
    if (second_ != nullptr) second_->on_frame(time_ns, frame, transmitted);
  }

 private:
  FrameTap& first_;
  FrameTap* second_;
};

class ToolLink : public hal::CanBus {
 public:
  bool send(const hal::CanFrame& frame) final;
  bool receive(hal::CanFrame& frame) final;
  [[nodiscard]] hal::CanBusCounters counters() const override = 0;

  // Waits until a frame may be pending or `deadline_ns` passes; false only at the deadline.
  virtual bool wait(std::int64_t deadline_ns) = 0;
  // Monotonic time for timeouts.
  virtual std::int64_t now_ns() = 0;
  // Wall time now, for logs (the sim's epoch is its start).
  virtual std::int64_t wall_time_ns() = 0;
  // Wall time the frame just received arrived (the kernel's stamp on a socket).
  virtual std::int64_t rx_time_ns() { return wall_time_ns(); }
  // The soil-wheel encoder (A/B edges); nullptr when the tool has no GPIO access.
  virtual hal::GpioEdgeSource* encoder() { return nullptr; }
  virtual SimFixture* fixture() { return nullptr; }
  [[nodiscard]] virtual std::string name() const = 0;
  [[nodiscard]] std::uint32_t paced_sends() const { return paced_; }
  [[nodiscard]] std::uint32_t lost_sends() const { return lost_; }

  void set_tap(FrameTap* tap) { tap_ = tap; }
  [[nodiscard]] FrameTap* tap() const { return tap_; }
  // Receives one frame, waiting up to the deadline.
  bool receive_until(hal::CanFrame& frame, std::int64_t deadline_ns);
  // Lets time pass until the deadline, taking (and dropping) what arrives so no queue fills.
  void idle_until(std::int64_t deadline_ns);

 protected:
  virtual bool try_send(const hal::CanFrame& frame) = 0;
  virtual bool try_receive(hal::CanFrame& frame) = 0;
  // Lets the transmit queue drain a little (a real bus: sleep; the sim: advance its clock).
  virtual void back_off() = 0;

 private:
  FrameTap* tap_ = nullptr;
  std::uint32_t paced_ = 0;
  std::uint32_t lost_ = 0;
};

}  // namespace planter::cantool
