#include "dem/contact_arrays.h"

namespace planter::dem {

namespace {

template <typename Fn>
void each_array(ContactArrays& c, Fn&& fn) {
  for (auto* a : {&c.rest_overlap_m, &c.constants.e_star, &c.constants.g_star, &c.constants.r_star,
                  &c.constants.m_star, &c.constants.beta, &c.constants.shear_to_normal_root,
                  &c.spring_x, &c.spring_y, &c.spring_z}) {
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
  constants.set(k, p);
  spring_x[k] = spring.x();
  spring_y[k] = spring.y();
  spring_z[k] = spring.z();
}

PairProperties ContactArrays::properties(std::size_t k) const { return constants.at(k); }

Vec3 ContactArrays::spring(std::size_t k) const { return {spring_x[k], spring_y[k], spring_z[k]}; }

}  // namespace planter::dem
