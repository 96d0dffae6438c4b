#include "dem/platen_arrays.h"

namespace planter::dem {

void PlatenArrays::resize(std::size_t platens, const std::vector<PairProperties>& properties) {
  particles = properties.size();
  for (auto* a : {&e_star, &g_star, &r_star, &m_star, &beta, &shear_to_normal_root}) {
    a->resize(particles);
  }
  for (std::size_t k = 0; k < particles; ++k) {
    const PairProperties& p = properties[k];
    e_star[k] = p.e_star;
    g_star[k] = p.g_star;
    r_star[k] = p.r_star;
    m_star[k] = p.m_star;
    beta[k] = p.beta;
    shear_to_normal_root[k] = p.shear_to_normal_root;
  }
  const std::size_t n = platens * particles;
  for (auto* a : {&spring_x, &spring_y, &spring_z}) a->resize(n, 0.0);
  for (auto* a : {&fx, &fy, &fz, &tx, &ty, &tz, &normal_N, &near}) a->assign(n, 0.0);
}

}  // namespace planter::dem
