#pragma once
#include "hal/sim/fixed_ring.h"
#include "planter/hal/gpio.h"

namespace planter::hal::sim {

// Edge events produced by the plant model (the soil wheel's encoder lines).
class SimEdgeSource final : public GpioEdgeSource {
 public:
  explicit SimEdgeSource(std::size_t capacity = 4096) : edges_(capacity) {}
  bool next_edge(GpioEdge& edge) override { return edges_.pop(edge); }
  [[nodiscard]] std::uint32_t overflow_count() const override { return overflow_; }
  void push(const GpioEdge& edge);

 private:
  FixedRing<GpioEdge> edges_;
  std::uint32_t overflow_ = 0;
};

class SimDigitalInput final : public DigitalInput {
 public:
  [[nodiscard]] bool asserted() const override { return asserted_; }
  void set(bool asserted) { asserted_ = asserted; }

 private:
  bool asserted_ = false;
};

class SimDigitalOutput final : public DigitalOutput {
 public:
  void set(bool on) override { on_ = on; }
  [[nodiscard]] bool on() const { return on_; }

 private:
  bool on_ = false;
};

}  // namespace planter::hal::sim
