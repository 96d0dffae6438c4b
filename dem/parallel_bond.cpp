#include "dem/parallel_bond.h"

#include <cmath>

namespace planter::dem {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Keeps a stored in-plane vector in the current contact plane with its magnitude (one square
// root: the ratio of the squared lengths).
[[gnu::always_inline]] inline void rotate_into_plane(Vec3& v, const Vec3& n) {
  const double mag2 = v.squaredNorm();
  if (mag2 == 0.0) return;
  v -= v.dot(n) * n;
  const double now2 = v.squaredNorm();
  v = now2 > 0.0 ? Vec3(v * std::sqrt(mag2 / now2)) : Vec3::Zero();
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

BondStep bond_step(const BondParameters& p, double dt) {
  const BondGeometry g = bond_geometry(p.radius_m);
  return {p.normal_stiffness_N_m3 * g.area_m2 * dt,
          p.shear_stiffness_N_m3 * g.area_m2 * dt,
          p.shear_stiffness_N_m3 * g.polar_m4 * dt,
          p.normal_stiffness_N_m3 * g.bending_m4 * dt,
          g.area_m2,
          p.radius_m / g.polar_m4,
          p.tensile_strength_Pa,
          p.shear_strength_Pa};
}

void update_bond(Bond& b, const BondStep& s, Particle& pi, Particle& pj) {
  if (b.broken) return;
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
  b.normal_force_N += -vn * s.normal_per_m;
  b.shear_force += -vt * s.shear_per_m;
  b.twist_moment += -wn * s.twist_per_rad;
  b.bending_moment += -wt * s.bending_per_rad;
  // Signed criteria (bond_tensile_stress, bond_shear_stress): compression lowers the tensile
  // stress, it never breaks a bond alone.
  const double tensile =
      -b.normal_force_N / s.area_m2 + 2.0 * b.bending_moment.norm() * s.rim_per_polar;
  const double shear =
      b.shear_force.norm() / s.area_m2 + std::fabs(b.twist_moment) * s.rim_per_polar;
  if (tensile > s.tensile_strength_Pa || shear > s.shear_strength_Pa) {
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
