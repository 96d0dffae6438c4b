#include "dem/particle_motion.h"

namespace planter::dem {

void ParticleMotion::assign(const std::vector<Particle>& particles) {
  const std::size_t n = particles.size();
  for (auto* a : {&x, &y, &z, &vx, &vy, &vz, &wx, &wy, &wz, &radius_m, &inv_spin}) a->resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Particle& p = particles[k];
    x[k] = p.x.x();
    y[k] = p.x.y();
    z[k] = p.x.z();
    vx[k] = p.v.x();
    vy[k] = p.v.y();
    vz[k] = p.v.z();
    wx[k] = p.w.x();
    wy[k] = p.w.y();
    wz[k] = p.w.z();
    radius_m[k] = p.radius_m;
    inv_spin[k] = inverse_spin(p.w);
  }
}

}  // namespace planter::dem
