#pragma once
// The particles' motion as the pair steps read it: one array per component, so that a vector
// lane gathers its pair's two particles (dem/lane_views.h). Copied from the particles once a
// step, before the pairs.
#include <vector>

#include "dem/particle.h"

namespace planter::dem {

// Position, velocity, angular velocity and radius of every particle, one array per component,
// and 1/|w| (0 for a particle that does not spin).
struct ParticleMotion {
  std::vector<double> x, y, z, vx, vy, vz, wx, wy, wz, radius_m, inv_spin;
  void assign(const std::vector<Particle>& particles);
};

}  // namespace planter::dem
