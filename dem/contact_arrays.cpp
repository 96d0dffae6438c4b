#include "dem/contact_arrays.h"

namespace planter::dem {

namespace {

template <typename Fn>
void each_array(ContactArrays& c, Fn&& fn) {
  for (auto* a : {&c.rest_overlap_m,
                  &c.e_star,
                  &c.g_star,
                  &c.r_star,
                  &c.m_star,
                  &c.beta,
                  &c.shear_to_normal_root,
                  &c.spring_x,
                  &c.spring_y,
                  &c.spring_z,
                  &c.force_on_i_x,
                  &c.force_on_i_y,
                  &c.force_on_i_z,
                  &c.torque_on_i_x,
                  &c.torque_on_i_y,
                  &c.torque_on_i_z,
                  &c.torque_on_j_x,
                  &c.torque_on_j_y,
                  &c.torque_on_j_z,
                  &c.touching}) {
    fn(*a);
  }
}

}  // namespace

void ContactArrays::clear() {
  i.clear();
  j.clear();
  bond.clear();
  each_array(*this, [](std::vector<double>& a) { a.clear(); });
}

void ContactArrays::push_back(int pi, int pj, int bond_index, double rest_overlap,
                              const PairProperties& p, const Vec3& spring) {
  i.push_back(pi);
  j.push_back(pj);
  bond.push_back(bond_index);
  each_array(*this, [](std::vector<double>& a) { a.push_back(0.0); });
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

void add_contact_load(const ContactArrays& c, std::size_t k, bool on_j, Particle& particle) {
  if (c.touching[k] == 0.0) return;
  const Vec3 f(c.force_on_i_x[k], c.force_on_i_y[k], c.force_on_i_z[k]);
  if (on_j) {
    particle.f -= f;
    particle.tau += Vec3(c.torque_on_j_x[k], c.torque_on_j_y[k], c.torque_on_j_z[k]);
  } else {
    particle.f += f;
    particle.tau += Vec3(c.torque_on_i_x[k], c.torque_on_i_y[k], c.torque_on_i_z[k]);
  }
}

void add_contact_loads(const ContactArrays& c, const Incidence& contacts_of, std::size_t p,
                       Particle& particle) {
  const auto end = static_cast<std::size_t>(contacts_of.start[p + 1]);
  for (auto e = static_cast<std::size_t>(contacts_of.start[p]); e < end; ++e) {
    add_contact_load(c, static_cast<std::size_t>(contacts_of.pair[e]), contacts_of.is_j[e] != 0,
                     particle);
  }
}

void add_all_contact_loads(const ContactArrays& c, std::vector<Particle>& particles) {
  // add_contact_load's two sides with one test and one read of the force.
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (c.touching[k] == 0.0) continue;
    Particle& a = particles[static_cast<std::size_t>(c.i[k])];
    Particle& b = particles[static_cast<std::size_t>(c.j[k])];
    const Vec3 f(c.force_on_i_x[k], c.force_on_i_y[k], c.force_on_i_z[k]);
    a.f += f;
    b.f -= f;
    a.tau += Vec3(c.torque_on_i_x[k], c.torque_on_i_y[k], c.torque_on_i_z[k]);
    b.tau += Vec3(c.torque_on_j_x[k], c.torque_on_j_y[k], c.torque_on_j_z[k]);
  }
}

}  // namespace planter::dem
