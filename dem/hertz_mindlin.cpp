#include "dem/hertz_mindlin.h"

#include <cmath>
#include <numbers>

#include "dem/contact_lane.h"

namespace planter::dem {
namespace {

double inverse_sum(double a_inv, double b_inv) {
  const double s = a_inv + b_inv;
  return s > 0.0 ? 1.0 / s : 0.0;
}

}  // namespace

PairProperties pair_properties(const ContactMaterial& m, double r_i, double r_j, double m_i,
                               double m_j) {
  return pair_properties(m, m, m.restitution, r_i, r_j, m_i, m_j);
}

PairProperties pair_properties(const ContactMaterial& mat_i, const ContactMaterial& mat_j, double e,
                               double r_i, double r_j, double m_i, double m_j) {
  const double e_i = mat_i.youngs_modulus_Pa();
  const double e_j = mat_j.youngs_modulus_Pa();
  const double nu_i = mat_i.poisson;
  const double nu_j = mat_j.poisson;
  PairProperties p;
  p.e_star = inverse_sum((1 - nu_i * nu_i) / e_i, (1 - nu_j * nu_j) / e_j);
  p.g_star = inverse_sum(2 * (2 - nu_i) * (1 + nu_i) / e_i, 2 * (2 - nu_j) * (1 + nu_j) / e_j);
  p.r_star = inverse_sum(std::isinf(r_i) ? 0.0 : 1.0 / r_i, std::isinf(r_j) ? 0.0 : 1.0 / r_j);
  p.m_star = inverse_sum(std::isinf(m_i) ? 0.0 : 1.0 / m_i, std::isinf(m_j) ? 0.0 : 1.0 / m_j);
  const double le = std::log(e);
  p.beta = e >= 1.0 ? 0.0 : le / std::sqrt(le * le + std::numbers::pi * std::numbers::pi);
  p.shear_to_normal_root = p.e_star > 0.0 ? std::sqrt(4.0 * p.g_star / p.e_star) : 0.0;
  return p;
}

double hertz_energy(const PairProperties& p, double overlap_m) {
  return overlap_m > 0.0 ? 8.0 / 15.0 * p.e_star * std::sqrt(p.r_star) * std::pow(overlap_m, 2.5)
                         : 0.0;
}

double hertz_normal_force(const PairProperties& p, double overlap_m) {
  return overlap_m > 0.0 ? 4.0 / 3.0 * p.e_star * std::sqrt(p.r_star) * std::pow(overlap_m, 1.5)
                         : 0.0;
}

ContactResult hertz_mindlin(const ContactMaterial& m, const PairProperties& p, const Particle& i,
                            const Particle& j, double dt, Vec3& spring, double rest_overlap_m) {
  auto sphere = [](const Particle& q) {
    return lanes::Sphere{q.x.x(), q.x.y(), q.x.z(), q.v.x(),    q.v.y(),          q.v.z(),
                         q.w.x(), q.w.y(), q.w.z(), q.radius_m, inverse_spin(q.w)};
  };
  double sx = spring.x();
  double sy = spring.y();
  double sz = spring.z();
  const lanes::ContactLoads l = lanes::contact_lane(m.friction, m.rolling_friction, p, sphere(i),
                                                    sphere(j), dt, rest_overlap_m, sx, sy, sz);
  spring = Vec3(sx, sy, sz);
  ContactResult r;
  r.force_on_i = Vec3(l.fx, l.fy, l.fz);
  r.torque_on_i = Vec3(l.ti_x, l.ti_y, l.ti_z);
  r.torque_on_j = Vec3(l.tj_x, l.tj_y, l.tj_z);
  r.normal_force_N = l.normal_N;
  r.sliding = l.sliding;
  return r;
}

}  // namespace planter::dem
