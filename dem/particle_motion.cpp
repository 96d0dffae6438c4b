#include "dem/particle_motion.h"

namespace planter::dem {

void ParticleMotion::assign(const std::vector<Particle>& particles) {
  const std::size_t n = particles.size();
  for (auto* a : {&x, &y, &z, &vx, &vy, &vz, &wx, &wy, &wz, &radius_m, &inv_spin}) a->resize(n);
  rows.resize(n * kRowWidth, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const Particle& p = particles[k];
    double* row = &rows[k * kRowWidth];
    row[0] = x[k] = p.x.x();
    row[1] = y[k] = p.x.y();
    row[2] = z[k] = p.x.z();
    row[3] = vx[k] = p.v.x();
    row[4] = vy[k] = p.v.y();
    row[5] = vz[k] = p.v.z();
    row[6] = wx[k] = p.w.x();
    row[7] = wy[k] = p.w.y();
    row[8] = wz[k] = p.w.z();
    row[9] = radius_m[k] = p.radius_m;
    row[10] = inv_spin[k] = inverse_spin(p.w);
  }
}

}  // namespace planter::dem
