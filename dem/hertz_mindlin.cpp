#include "dem/hertz_mindlin.h"

#include <cmath>

namespace planter::dem {
namespace {

constexpr double kPi = 3.14159265358979323846;

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
  p.beta = e >= 1.0 ? 0.0 : le / std::sqrt(le * le + kPi * kPi);
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
  ContactResult r;
  const Vec3 d = j.x - i.x;
  const double dist = d.norm();
  const double overlap = i.radius_m + j.radius_m - rest_overlap_m - dist;
  if (overlap <= 0.0 || dist <= 0.0) {
    spring.setZero();
    return r;
  }
  const Vec3 n = d / dist;  // from i to j
  // Relative velocity of j's surface against i's at the contact point.
  const Vec3 vc = (j.v + j.w.cross(-j.radius_m * n)) - (i.v + i.w.cross(i.radius_m * n));
  const double vn = vc.dot(n);
  const Vec3 vt = vc - vn * n;
  const double sqrt_rd = std::sqrt(p.r_star * overlap);
  const double s_n = 2.0 * p.e_star * sqrt_rd;
  const double s_t = 8.0 * p.g_star * sqrt_rd;
  constexpr double kSqrt56 = 0.91287092917527690;  // sqrt(5/6)
  // hertz_normal_force without its pow: 4/3 E* sqrt(R* d) d = 2/3 s_n d.
  const double fn_elastic = 2.0 / 3.0 * s_n * overlap;
  // Damping opposes the relative motion (beta < 0): less push while separating (vn > 0).
  const double fn_damp = 2.0 * kSqrt56 * p.beta * std::sqrt(s_n * p.m_star) * vn;
  const double fn = std::max(0.0, fn_elastic + fn_damp);
  // Tangential spring: keep it in the contact plane, add this step's displacement.
  spring -= spring.dot(n) * n;
  spring += s_t * vt * dt;
  Vec3 ft = spring - 2.0 * kSqrt56 * p.beta * std::sqrt(s_t * p.m_star) * vt;
  const double ft_max = m.friction * fn;
  if (ft.norm() > ft_max) {
    r.sliding = true;
    ft = ft_max * ft.normalized();
    spring = ft;
  }
  // On i: pushed away along -n, dragged along the relative tangential motion.
  r.force_on_i = -fn * n + ft;
  r.normal_force_N = fn;
  r.torque_on_i = (i.radius_m * n).cross(ft);
  r.torque_on_j = (-j.radius_m * n).cross(-ft);
  // Rolling friction opposes each particle's own rotation.
  auto rolling = [&](const Particle& q) -> Vec3 {
    const double wn = q.w.norm();
    return wn > 0.0 ? Vec3(-m.rolling_friction * fn * q.radius_m * q.w / wn) : Vec3::Zero();
  };
  r.torque_on_i += rolling(i);
  r.torque_on_j += rolling(j);
  return r;
}

}  // namespace planter::dem
