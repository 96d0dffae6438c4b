#pragma once
// The towed soil wheel and its quadrature encoder: rolls with slip, and turns each count
// change into an A or B edge with a timestamp inside the step.
#include <cmath>
#include <cstdint>

#include "hal/sim/sim_gpio.h"

namespace planter::sim {

class SoilWheelEncoder {
 public:
  SoilWheelEncoder(double radius_m, std::uint32_t counts_per_rev)
      : radius_m_(radius_m), cpr_(counts_per_rev) {}

  // The wheel rolls `ground_distance_m * (1 - slip)` during [t0, t0 + dt].
  void roll(double ground_distance_m, double slip, std::int64_t t0_ns, std::int64_t dt_ns,
            hal::sim::SimEdgeSource& edges) {
    constexpr double kTwoPi = 6.283185307179586;
    const double angle0 = angle_rad_;
    angle_rad_ += ground_distance_m * (1.0 - slip) / radius_m_;
    const auto target = static_cast<std::int64_t>(std::floor(angle_rad_ / kTwoPi * cpr_));
    const double span = angle_rad_ - angle0;
    while (count_ != target) {
      const bool forward = target > count_;
      const std::int64_t next = forward ? count_ + 1 : count_ - 1;
      // Time of the crossing, interpolated linearly within the step.
      const double boundary = static_cast<double>(forward ? next : count_) * kTwoPi / cpr_;
      const double frac = span != 0.0 ? std::clamp((boundary - angle0) / span, 0.0, 1.0) : 1.0;
      const auto t = t0_ns + static_cast<std::int64_t>(frac * static_cast<double>(dt_ns));
      // Gray index 0=(A0,B0) 1=(A0,B1) 2=(A1,B1) 3=(A1,B0): forward 0->1 B rises, 1->2 A rises...
      const int from = static_cast<int>(((count_ % 4) + 4) % 4);
      const int to = static_cast<int>(((next % 4) + 4) % 4);
      const int changed =
          ((from ^ to) == 1 || (from ^ to) == 3) ? ((from + to == 1 || from + to == 5) ? 1 : 0) : 0;
      const bool a = to >= 2;
      const bool b = to == 1 || to == 2;
      edges.push({static_cast<std::uint8_t>(changed), changed == 0 ? a : b, t});
      count_ = next;
    }
  }
  [[nodiscard]] std::int64_t count() const { return count_; }

 private:
  double radius_m_;
  double cpr_;
  double angle_rad_ = 0.0;
  std::int64_t count_ = 0;
};

}  // namespace planter::sim
