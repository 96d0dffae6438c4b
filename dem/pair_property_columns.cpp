#include "dem/pair_property_columns.h"

namespace planter::dem {

void PairPropertyColumns::resize(std::size_t rows) {
  for (auto* a : {&e_star, &g_star, &r_star, &m_star, &beta, &shear_to_normal_root}) {
    a->resize(rows, 0.0);
  }
}

void PairPropertyColumns::set(std::size_t row, const PairProperties& p) {
  e_star[row] = p.e_star;
  g_star[row] = p.g_star;
  r_star[row] = p.r_star;
  m_star[row] = p.m_star;
  beta[row] = p.beta;
  shear_to_normal_root[row] = p.shear_to_normal_root;
}

PairProperties PairPropertyColumns::at(std::size_t row) const {
  return {e_star[row], g_star[row], r_star[row], m_star[row], beta[row], shear_to_normal_root[row]};
}

}  // namespace planter::dem
