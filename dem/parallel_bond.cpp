#include "dem/parallel_bond.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "dem/bond_kernel.h"
#include "dem/particle_motion.h"

namespace planter::dem {
BondGeometry bond_geometry(double r) {
  const double r2 = r * r;  // products, not pow: this runs for every bond every step
  const double j = std::numbers::pi * r2 * r2 / 2.0;
  return {std::numbers::pi * r2, j, j / 2.0};
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
          1.0 / g.area_m2,
          p.radius_m / g.polar_m4,
          p.tensile_strength_Pa,
          p.shear_strength_Pa};
}

void update_bond(Bond& b, const BondStep& s, Particle& pi, Particle& pj) {
  BondArrays one;
  Bond local = b;
  local.i = 0;
  local.j = 1;
  one.push_back(local);
  std::vector<Particle> pair{pi, pj};
  ParticleMotion motion;
  motion.assign(pair, reads_motion_rows(VectorPath::kScalar));
  update_bonds(VectorPath::kScalar, one, motion, s, 0, 1);
  add_all_pair_loads(one.loads, one.i, one.j, pair);
  local = one.bond(0);
  local.i = b.i;
  local.j = b.j;
  b = local;
  pi = pair[0];
  pj = pair[1];
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
