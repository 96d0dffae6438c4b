#include "dem/contact_arrays.h"

namespace planter::dem {

namespace {

template <typename Fn>
void each_array(ContactArrays& c, Fn&& fn) {
  for (auto* a : {&c.rest_overlap_m, &c.e_star, &c.g_star, &c.r_star, &c.m_star, &c.beta,
                  &c.shear_to_normal_root, &c.spring_x, &c.spring_y, &c.spring_z}) {
    fn(*a);
  }
}

}  // namespace

void ContactArrays::clear() {
  i.clear();
  j.clear();
  bond.clear();
  each_array(*this, [](std::vector<double>& a) { a.clear(); });
  loads.clear();
}

void ContactArrays::push_back(int pi, int pj, int bond_index, double rest_overlap,
                              const PairProperties& p, const Vec3& spring) {
  i.push_back(pi);
  j.push_back(pj);
  bond.push_back(bond_index);
  each_array(*this, [](std::vector<double>& a) { a.push_back(0.0); });
  loads.resize(i.size());
  const std::size_t k = i.size() - 1;
  rest_overlap_m[k] = rest_overlap;
  e_star[k] = p.e_star;
  g_star[k] = p.g_star;
  r_star[k] = p.r_star;
  m_star[k] = p.m_star;
  beta[k] = p.beta;
  shear_to_normal_root[k] = p.shear_to_normal_root;
  spring_x[k] = spring.x();
  spring_y[k] = spring.y();
  spring_z[k] = spring.z();
}

PairProperties ContactArrays::properties(std::size_t k) const {
  return {e_star[k], g_star[k], r_star[k], m_star[k], beta[k], shear_to_normal_root[k]};
}

Vec3 ContactArrays::spring(std::size_t k) const { return {spring_x[k], spring_y[k], spring_z[k]}; }

}  // namespace planter::dem
