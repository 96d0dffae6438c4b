#include "dem/parallel_bond.h"

#include <cmath>

namespace planter::dem {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Keeps a stored in-plane vector in the current contact plane with its magnitude.
void rotate_into_plane(Vec3& v, const Vec3& n) {
  const double mag = v.norm();
  if (mag == 0.0) return;
  v -= v.dot(n) * n;
  const double now = v.norm();
  v = now > 0.0 ? Vec3(v * (mag / now)) : Vec3::Zero();
}

}  // namespace

BondGeometry bond_geometry(double r) {
  const double r2 = r * r;  // products, not pow: this runs for every bond every step
  const double j = kPi * r2 * r2 / 2.0;
  return {kPi * r2, j, j / 2.0};
}

double bond_tensile_stress(const Bond& b, const BondParameters& p) {
  const BondGeometry g = bond_geometry(p.radius_m);
  return -b.normal_force_N / g.area_m2 + 2.0 * b.bending_moment.norm() * p.radius_m / g.polar_m4;
}

double bond_shear_stress(const Bond& b, const BondParameters& p) {
  const BondGeometry g = bond_geometry(p.radius_m);
  return b.shear_force.norm() / g.area_m2 + std::fabs(b.twist_moment) * p.radius_m / g.polar_m4;
}

void update_bond(Bond& b, const BondParameters& p, Particle& pi, Particle& pj, double dt) {
  if (b.broken) return;
  const BondGeometry g = bond_geometry(p.radius_m);
  const Vec3 d = pj.x - pi.x;
  const double dist = d.norm();
  if (dist <= 0.0) return;
  const Vec3 n = d / dist;
  // Contact point halfway across the gap between the surfaces.
  const double to_contact_i = pi.radius_m + 0.5 * (dist - pi.radius_m - pj.radius_m);
  const Vec3 ri = to_contact_i * n;
  const Vec3 rj = ri - d;
  const Vec3 vc = (pj.v + pj.w.cross(rj)) - (pi.v + pi.w.cross(ri));
  const double vn = vc.dot(n);
  const Vec3 vt = vc - vn * n;
  const Vec3 wr = pj.w - pi.w;
  const double wn = wr.dot(n);
  const Vec3 wt = wr - wn * n;
  rotate_into_plane(b.shear_force, n);
  rotate_into_plane(b.bending_moment, n);
  b.normal_force_N += -vn * p.normal_stiffness_N_m3 * g.area_m2 * dt;
  b.shear_force += -vt * p.shear_stiffness_N_m3 * g.area_m2 * dt;
  b.twist_moment += -wn * p.shear_stiffness_N_m3 * g.polar_m4 * dt;
  b.bending_moment += -wt * p.normal_stiffness_N_m3 * g.bending_m4 * dt;
  // Signed criteria: compression lowers the tensile stress, it never breaks a bond alone.
  if (bond_tensile_stress(b, p) > p.tensile_strength_Pa ||
      bond_shear_stress(b, p) > p.shear_strength_Pa) {
    b.broken = true;
    return;
  }
  const Vec3 f_on_j = b.normal_force_N * n + b.shear_force;
  const Vec3 m_on_j = b.twist_moment * n + b.bending_moment;
  pj.f += f_on_j;
  pi.f -= f_on_j;
  pj.tau += m_on_j + rj.cross(f_on_j);
  pi.tau += -m_on_j + ri.cross(-f_on_j);
}

double bond_energy(const Bond& b, const BondParameters& p) {
  if (b.broken) return 0.0;
  const BondGeometry g = bond_geometry(p.radius_m);
  const double kn = p.normal_stiffness_N_m3 * g.area_m2;
  const double kt = p.shear_stiffness_N_m3 * g.area_m2;
  const double ktw = p.shear_stiffness_N_m3 * g.polar_m4;
  const double kb = p.normal_stiffness_N_m3 * g.bending_m4;
  return 0.5 * (b.normal_force_N * b.normal_force_N / kn + b.shear_force.squaredNorm() / kt +
                b.twist_moment * b.twist_moment / ktw + b.bending_moment.squaredNorm() / kb);
}

}  // namespace planter::dem
