#pragma once
// Forward motion of the machine along the row: the driver's speed with variation, planned
// stops, acceleration limits; and the micro-terrain under it.
#include <cmath>

#include "sim/plant/plant_config.h"

namespace planter::sim {

class Ground {
 public:
  Ground(const RouteConfig& route, const TerrainConfig& terrain)
      : route_(route), terrain_(terrain) {}

  void step(double t_s, double dt_s) {
    double wanted = 0.0;
    if (moving_ && x_m_ < route_.distance_m) {
      constexpr double kTwoPi = 6.283185307179586;
      wanted =
          route_.speed_mps * (1.0 + 0.01 * route_.speed_variation_pct *
                                        std::sin(kTwoPi * t_s / route_.speed_variation_period_s));
      // Brake to reach the end and each stop point at rest.
      const double to_end = route_.distance_m - x_m_;
      wanted = std::min(wanted, std::sqrt(2.0 * route_.accel_mps2 * std::max(0.0, to_end)));
      for (std::size_t i = 0; i < route_.stops.size(); ++i) {
        const StopEvent& s = route_.stops[i];
        if (stop_done_mask_ & (1u << i)) continue;
        const double to_stop = s.at_m - x_m_;
        if (to_stop <= 1e-4) {
          if (dwell_until_s_ < 0.0) dwell_until_s_ = t_s + s.duration_s;
          if (t_s < dwell_until_s_) {
            wanted = 0.0;
            dwelling_stop_ = static_cast<int>(i);
          } else {
            stop_done_mask_ |= 1u << i;
            dwell_until_s_ = -1.0;
            dwelling_stop_ = -1;
          }
        } else {
          wanted = std::min(wanted, std::sqrt(2.0 * route_.accel_mps2 * to_stop));
        }
      }
    }
    const double dv = route_.accel_mps2 * dt_s;
    v_mps_ += std::clamp(wanted - v_mps_, -dv, dv);
    x_m_ += v_mps_ * dt_s;
    terrain_mm_ = terrain_at(x_m_);
  }

  void start() { moving_ = true; }
  [[nodiscard]] double x_m() const { return x_m_; }
  [[nodiscard]] double v_mps() const { return v_mps_; }
  // The stop the machine is standing at (index into the route's stops), or -1.
  [[nodiscard]] int dwelling_stop() const { return dwelling_stop_; }
  [[nodiscard]] double dwell_until_s() const { return dwell_until_s_; }
  [[nodiscard]] bool finished() const { return x_m_ >= route_.distance_m - 1e-3 && v_mps_ < 1e-4; }
  // Terrain height (mm) under the machine, computed once a step (the plant asks for it
  // several times a step).
  [[nodiscard]] double terrain_mm() const { return terrain_mm_; }

 private:
  // Two incommensurate waves.
  [[nodiscard]] double terrain_at(double x_m) const {
    constexpr double kTwoPi = 6.283185307179586;
    const double k = kTwoPi / terrain_.wavelength_m;
    return terrain_.roughness_mm * (0.7 * std::sin(k * x_m) + 0.3 * std::sin(2.71 * k * x_m + 1.3));
  }

  RouteConfig route_;
  TerrainConfig terrain_;
  bool moving_ = false;
  double x_m_ = 0.0;
  double v_mps_ = 0.0;
  double terrain_mm_ = terrain_at(0.0);
  double dwell_until_s_ = -1.0;
  int dwelling_stop_ = -1;
  unsigned stop_done_mask_ = 0;
};

}  // namespace planter::sim
