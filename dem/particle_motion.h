#pragma once
// The particles' motion as the pair steps read it: one array per component, so that a vector
// lane gathers its pair's two particles (dem/lane_views.h). Copied from the particles once a
// step, before the pairs.
#include <array>
#include <cstddef>
#include <vector>

#include "dem/particle.h"

namespace planter::dem {

// Position, velocity, angular velocity and radius of every particle, one array per component,
// and 1/|w| (0 for a particle that does not spin).
struct ParticleMotion {
  // Per particle in `rows`: the kRowValues values below in their order (x ... inv_spin), then
  // zeros to kRowWidth: two 512-bit vectors, so that the AVX-512 lanes load a particle whole
  // and transpose eight (dem/lanes_simd.cpp).
  static constexpr std::size_t kRowValues = 11;
  static constexpr std::size_t kRowWidth = 16;
  std::vector<double> x, y, z, vx, vy, vz, wx, wy, wz, radius_m, inv_spin;
  std::vector<double> rows;  // filled only when asked for (with_rows), else empty
  void assign(const std::vector<Particle>& particles, bool with_rows);

 private:
  // The columns in a row's order.
  std::array<std::vector<double>*, kRowValues> columns() {
    return {&x, &y, &z, &vx, &vy, &vz, &wx, &wy, &wz, &radius_m, &inv_spin};
  }
};

}  // namespace planter::dem
