#pragma once
// The seedling's radial force response reduced from the bonded-particle DEM (planter-dem
// reduce): F(delta, delta_dot) = k(d) delta^n + c delta_dot up to the first peak F_p(d) at
// delta_p(d), where the wall collapses to a residual share of the peak. k, F_p and delta_p
// are linear in the seedling's diameter d around a reference diameter.
#include <algorithm>
#include <cmath>

namespace planter::sim {

struct SeedlingForceModel {
  bool loaded = false;
  double reference_diameter_mm = 10.0;
  double exponent = 1.0;                   // n
  double stiffness_N_per_mm_n = 30.0;      // k at the reference diameter
  double stiffness_slope_per_mm = 0.0;     // dk/dd
  double peak_force_N = 140.6;             // F_p at the reference diameter
  double peak_force_slope_N_per_mm = 0.0;  // dF_p/dd
  double peak_displacement_mm = 4.0;       // delta_p at the reference diameter
  double peak_displacement_slope = 0.0;    // d(delta_p)/dd, mm per mm
  double residual_fraction = 0.5;          // force after the collapse / F_p
  double damping_N_s_per_mm = 0.0;         // c

  [[nodiscard]] double stiffness(double d_mm) const {
    return std::max(1e-6,
                    stiffness_N_per_mm_n + stiffness_slope_per_mm * (d_mm - reference_diameter_mm));
  }
  [[nodiscard]] double peak_force(double d_mm) const {
    return std::max(1.0, peak_force_N + peak_force_slope_N_per_mm * (d_mm - reference_diameter_mm));
  }
  // Force at compression delta (mm) and its rate (mm/s), before any collapse.
  [[nodiscard]] double force_N(double d_mm, double delta_mm, double rate_mm_s) const {
    if (delta_mm <= 0.0) return 0.0;
    return stiffness(d_mm) * std::pow(delta_mm, exponent) + damping_N_s_per_mm * rate_mm_s;
  }
  // The quasi-static compression a force produces on the elastic branch.
  [[nodiscard]] double compression_mm(double d_mm, double force) const {
    if (force <= 0.0) return 0.0;
    return std::pow(force / stiffness(d_mm), 1.0 / exponent);
  }
};

}  // namespace planter::sim
