#pragma once
// One Hertz-Mindlin contact's step on plain numbers (the law: hertz_mindlin.h), with no branch:
// every choice is a select, so the same source runs one contact at a time (hertz_mindlin(), the
// platens) or one candidate pair per vector lane (dem/lanes_simd.cpp) with the same arithmetic.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "dem/hertz_mindlin.h"
#include "dem/lane_views.h"

namespace planter::dem::lanes {

// The loads of one contact: the force on i, the torques on i and j, the normal force.
struct ContactLoads {
  double fx, fy, fz, ti_x, ti_y, ti_z, tj_x, tj_y, tj_z, normal_N;
  bool touching, sliding;
};

// `sx, sy, sz` is the contact's tangential spring, carried between steps (zeroed when the
// spheres part). The overlap counts from `rest_overlap_m`.
[[gnu::always_inline]] inline ContactLoads contact_lane(double friction, double rolling_friction,
                                                        const PairProperties& p, const Sphere& i,
                                                        const Sphere& j, double dt,
                                                        double rest_overlap_m, double& sx,
                                                        double& sy, double& sz) {
  constexpr double kSqrt56 = 0.91287092917527690;  // sqrt(5/6)
  const double dx = j.x - i.x;
  const double dy = j.y - i.y;
  const double dz = j.z - i.z;
  const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
  const double overlap = i.r + j.r - rest_overlap_m - dist;
  const bool touching = (overlap > 0.0) & (dist > 0.0);
  // Every lane computes; a lane not touching selects zeros below (its NaNs are not used).
  const double inv_dist = 1.0 / dist;  // one division, not three
  const double nx = dx * inv_dist;     // from i to j
  const double ny = dy * inv_dist;
  const double nz = dz * inv_dist;
  // Relative velocity of j's surface against i's at the contact point: v + w x (r n) with
  // r n = -r_j n on j and r_i n on i.
  const double rjn_x = -j.r * nx;
  const double rjn_y = -j.r * ny;
  const double rjn_z = -j.r * nz;
  const double rin_x = i.r * nx;
  const double rin_y = i.r * ny;
  const double rin_z = i.r * nz;
  const double vcx =
      (j.vx + (j.wy * rjn_z - j.wz * rjn_y)) - (i.vx + (i.wy * rin_z - i.wz * rin_y));
  const double vcy =
      (j.vy + (j.wz * rjn_x - j.wx * rjn_z)) - (i.vy + (i.wz * rin_x - i.wx * rin_z));
  const double vcz =
      (j.vz + (j.wx * rjn_y - j.wy * rjn_x)) - (i.vz + (i.wx * rin_y - i.wy * rin_x));
  const double vn = vcx * nx + vcy * ny + vcz * nz;
  const double vtx = vcx - vn * nx;
  const double vty = vcy - vn * ny;
  const double vtz = vcz - vn * nz;
  const double sqrt_rd = std::sqrt(p.r_star * overlap);
  const double s_n = 2.0 * p.e_star * sqrt_rd;
  const double s_t = 8.0 * p.g_star * sqrt_rd;
  // hertz_normal_force without its pow: 4/3 E* sqrt(R* d) d = 2/3 s_n d.
  const double fn_elastic = 2.0 / 3.0 * s_n * overlap;
  // Damping opposes the relative motion (beta < 0): less push while separating (vn > 0).
  const double damp_n = 2.0 * kSqrt56 * p.beta * std::sqrt(s_n * p.m_star);
  const double fn_damp = damp_n * vn;
  const double fn = std::max(0.0, fn_elastic + fn_damp);
  // Tangential spring: kept in the contact plane, this step's displacement added.
  const double along = sx * nx + sy * ny + sz * nz;
  const double kx = (sx - along * nx) + s_t * vtx * dt;
  const double ky = (sy - along * ny) + s_t * vty * dt;
  const double kz = (sz - along * nz) + s_t * vtz * dt;
  // sqrt(s_t m*) = sqrt(s_n m*) sqrt(4 G*/E*): the pair's constant root, not a second one here.
  const double c_t = damp_n * p.shear_to_normal_root;
  double ftx = kx - c_t * vtx;
  double fty = ky - c_t * vty;
  double ftz = kz - c_t * vtz;
  // Coulomb's limit: a sliding contact's force is capped, and its spring is the capped force.
  const double ft_max = friction * fn;
  const double ft_norm = std::sqrt(ftx * ftx + fty * fty + ftz * ftz);
  const bool sliding = ft_norm > ft_max;
  const double cap = ft_max / ft_norm;
  ftx = sliding ? ftx * cap : ftx;
  fty = sliding ? fty * cap : fty;
  ftz = sliding ? ftz * cap : ftz;
  sx = touching ? (sliding ? ftx : kx) : 0.0;
  sy = touching ? (sliding ? fty : ky) : 0.0;
  sz = touching ? (sliding ? ftz : kz) : 0.0;
  // Rolling friction (EDEM type A) opposes each sphere's own rotation.
  const double roll_i = -rolling_friction * fn * i.r * i.inv_spin;
  const double roll_j = -rolling_friction * fn * j.r * j.inv_spin;
  ContactLoads out;
  // On i: pushed away along -n, dragged along the relative tangential motion.
  out.fx = touching ? -fn * nx + ftx : 0.0;
  out.fy = touching ? -fn * ny + fty : 0.0;
  out.fz = touching ? -fn * nz + ftz : 0.0;
  // (r_i n) x ft on i; (-r_j n) x (-ft) = (r_j n) x ft on j; each plus its rolling torque.
  out.ti_x = touching ? (rin_y * ftz - rin_z * fty) + roll_i * i.wx : 0.0;
  out.ti_y = touching ? (rin_z * ftx - rin_x * ftz) + roll_i * i.wy : 0.0;
  out.ti_z = touching ? (rin_x * fty - rin_y * ftx) + roll_i * i.wz : 0.0;
  out.tj_x = touching ? (rjn_z * fty - rjn_y * ftz) + roll_j * j.wx : 0.0;
  out.tj_y = touching ? (rjn_x * ftz - rjn_z * ftx) + roll_j * j.wy : 0.0;
  out.tj_z = touching ? (rjn_y * ftx - rjn_x * fty) + roll_j * j.wz : 0.0;
  out.normal_N = touching ? fn : 0.0;
  out.touching = touching;
  out.sliding = touching & sliding;
  return out;
}

// Candidate pair k of the arrays, its particles' spheres `i` and `j`: its loads and spring back
// into the arrays.
[[gnu::always_inline]] inline void contact_pair_lane(const ContactView& c, const Sphere& i,
                                                     const Sphere& j, const ContactStep& s,
                                                     std::size_t k) {
  const PairProperties p = c.constants.at(k);
  double sx = c.sx[k];
  double sy = c.sy[k];
  double sz = c.sz[k];
  const ContactLoads l =
      contact_lane(s.friction, s.rolling_friction, p, i, j, s.dt, c.rest[k], sx, sy, sz);
  c.sx[k] = sx;
  c.sy[k] = sy;
  c.sz[k] = sz;
  c.out.fx[k] = l.fx;
  c.out.fy[k] = l.fy;
  c.out.fz[k] = l.fz;
  c.out.ti_x[k] = l.ti_x;
  c.out.ti_y[k] = l.ti_y;
  c.out.ti_z[k] = l.ti_z;
  c.out.tj_x[k] = l.tj_x;
  c.out.tj_y[k] = l.tj_y;
  c.out.tj_z[k] = l.tj_z;
  c.out.carried[k] = l.touching ? 1.0 : 0.0;
}

// Particle k against one platen: a wall is a sphere of infinite radius and mass at the
// particle's foot point (radius 1 m stands in: R* below treats it as flat), and only a particle
// within its radius of the platen is in contact; the others' springs are released.
[[gnu::always_inline]] inline void platen_lane(const PlatenView& c, const MotionView& m,
                                               const PlatenStep& s, std::size_t k) {
  constexpr double kWallRadius = 1.0;
  const double h = (m.x[k] - s.px) * s.nx + (m.y[k] - s.py) * s.ny + (m.z[k] - s.pz) * s.nz;
  const bool near = h < m.r[k];
  const double foot = h + kWallRadius;
  const Sphere i = sphere_of(m, k);
  const Sphere wall{m.x[k] - foot * s.nx,
                    m.y[k] - foot * s.ny,
                    m.z[k] - foot * s.nz,
                    s.vx,
                    s.vy,
                    s.vz,
                    0.0,
                    0.0,
                    0.0,
                    kWallRadius,
                    0.0};
  const PairProperties p = c.constants.at(k);
  double sx = c.sx[k];
  double sy = c.sy[k];
  double sz = c.sz[k];
  const ContactLoads l = contact_lane(s.contact.friction, s.contact.rolling_friction, p, i, wall,
                                      s.contact.dt, 0.0, sx, sy, sz);
  c.sx[k] = near ? sx : 0.0;
  c.sy[k] = near ? sy : 0.0;
  c.sz[k] = near ? sz : 0.0;
  c.fx[k] = near ? l.fx : 0.0;
  c.fy[k] = near ? l.fy : 0.0;
  c.fz[k] = near ? l.fz : 0.0;
  c.tx[k] = near ? l.ti_x : 0.0;
  c.ty[k] = near ? l.ti_y : 0.0;
  c.tz[k] = near ? l.ti_z : 0.0;
  c.normal_N[k] = near ? l.normal_N : 0.0;
  c.near[k] = near ? 1.0 : 0.0;
}

}  // namespace planter::dem::lanes
