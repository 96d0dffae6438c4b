#pragma once
// Raw pointers into the DEM's arrays (bonds, candidate pairs, the particles' motion), taken
// once per step for the lane-wise kernels (dem/bond_lane.h, dem/contact_lane.h).
#include "dem/bond_arrays.h"
#include "dem/contact_arrays.h"
#include "dem/particle_motion.h"
#include "dem/platen_arrays.h"

namespace planter::dem::lanes {

// A step's loads (PairLoads): the force on i, the torques on i and j, whether carried.
struct LoadsView {
  double *fx, *fy, *fz, *ti_x, *ti_y, *ti_z, *tj_x, *tj_y, *tj_z, *carried;
};
struct BondView {
  const int* i;
  const int* j;
  double *fn, *twist, *sx, *sy, *sz, *bx, *by, *bz, *broken;
  LoadsView out;
};
// PairPropertyColumns, row by row.
struct PropertiesView {
  const double *e_star, *g_star, *r_star, *m_star, *beta, *shear_to_normal_root;
  [[gnu::always_inline]] PairProperties at(std::size_t k) const {
    return {e_star[k], g_star[k], r_star[k], m_star[k], beta[k], shear_to_normal_root[k]};
  }
};
struct ContactView {
  const int* i;
  const int* j;
  const double* rest;
  PropertiesView constants;
  double *sx, *sy, *sz;
  LoadsView out;
};
struct MotionView {
  const double *x, *y, *z, *vx, *vy, *vz, *wx, *wy, *wz, *r, *inv_spin;
  const double* rows;  // ParticleMotion::rows
};
// What every candidate pair's step shares.
struct ContactStep {
  double friction;
  double rolling_friction;
  double dt;
};
// One platen's contacts with every particle: the particles' constants against it, and its
// springs and loads (offset to that platen's rows).
struct PlatenView {
  PropertiesView constants;
  double *sx, *sy, *sz, *fx, *fy, *fz, *tx, *ty, *tz, *normal_N, *near;
};
// What a platen's step shares: the platen material's friction, the time step, and the platen
// (a point on it, its unit normal towards the particles, its velocity).
struct PlatenStep {
  ContactStep contact;
  double px, py, pz, nx, ny, nz, vx, vy, vz;
};
// A sphere's centre, velocity, angular velocity, radius, and 1/|w| (0 when it does not spin:
// the rolling torque's direction, worked out once a step per particle, not per contact).
struct Sphere {
  double x, y, z, vx, vy, vz, wx, wy, wz, r, inv_spin;
};

// Particle k's sphere from the particles' motion.
[[gnu::always_inline]] inline Sphere sphere_of(const MotionView& m, std::size_t k) {
  return {m.x[k],  m.y[k],  m.z[k],  m.vx[k], m.vy[k],      m.vz[k],
          m.wx[k], m.wy[k], m.wz[k], m.r[k],  m.inv_spin[k]};
}

BondView view(BondArrays& b);
ContactView view(ContactArrays& c);
MotionView view(const ParticleMotion& m);
PropertiesView view(const PairPropertyColumns& c);
// Platen `platen`'s rows of the arrays.
PlatenView view(PlatenArrays& a, std::size_t platen);

}  // namespace planter::dem::lanes
