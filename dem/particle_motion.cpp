#include "dem/particle_motion.h"

namespace planter::dem {

void ParticleMotion::assign(const std::vector<Particle>& particles, bool with_rows) {
  const std::size_t n = particles.size();
  const auto in_row_order = columns();
  for (auto* column : in_row_order) column->resize(n);
  rows.resize(with_rows ? n * kRowWidth : 0, 0.0);
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
    if (!with_rows) continue;
    double* row = &rows[k * kRowWidth];
    for (const auto* column : in_row_order) *row++ = (*column)[k];
  }
}

}  // namespace planter::dem
