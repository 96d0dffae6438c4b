#pragma once
// One bond's step, lane-wise: the same source runs one bond at a time (the scalar path) or one
// bond per vector lane (dem/lanes_simd.cpp). No branch: every choice is a select, and the
// arithmetic is the same in both (IEEE square roots and divisions, no contraction: the dem
// library is built with -ffp-contract=off), so the paths give bit-identical results.
// The law: Potyondy and Cundall (2004), "A bonded-particle model for rock", the parallel bond's
// incremental loads and its breakage criteria (dem/parallel_bond.h states it in full).
#include <cmath>
#include <cstddef>

#include "dem/lane_views.h"

namespace planter::dem::lanes {

// Keeps a stored in-plane vector (a, b, c) in the plane normal to n with its magnitude (one
// square root: the ratio of the squared lengths). Zero stays as it was.
[[gnu::always_inline]] inline void rotate_into_plane(double& a, double& b, double& c, double nx,
                                                     double ny, double nz) {
  const double mag2 = a * a + b * b + c * c;
  const double along = a * nx + b * ny + c * nz;
  const double pa = a - along * nx;
  const double pb = b - along * ny;
  const double pc = c - along * nz;
  const double now2 = pa * pa + pb * pb + pc * pc;
  // Computed in every lane, used where it is defined (a 0/0 lane is not selected).
  const double root = std::sqrt(mag2 / now2);
  const double scale = now2 > 0.0 ? root : 0.0;
  const bool keep = mag2 == 0.0;
  a = keep ? a : pa * scale;
  b = keep ? b : pb * scale;
  c = keep ? c : pc * scale;
}

// Bond k of the arrays, its particles' spheres `i` and `j`.
[[gnu::always_inline]] inline void bond_lane(const BondView& b, const Sphere& i, const Sphere& j,
                                             const BondStep& s, std::size_t k) {
  const double dx = j.x - i.x;
  const double dy = j.y - i.y;
  const double dz = j.z - i.z;
  const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
  // A broken bond, or two particles at one point (no direction), carries nothing and keeps
  // its stored loads.
  const double was_broken = b.broken[k];
  const bool live = (was_broken == 0.0) & (dist > 0.0);
  const double inv_dist = 1.0 / dist;
  const double nx = dx * inv_dist;
  const double ny = dy * inv_dist;
  const double nz = dz * inv_dist;
  // Contact point halfway across the gap between the surfaces.
  const double to_contact_i = i.r + 0.5 * (dist - i.r - j.r);
  const double rix = to_contact_i * nx;
  const double riy = to_contact_i * ny;
  const double riz = to_contact_i * nz;
  const double rjx = rix - dx;
  const double rjy = riy - dy;
  const double rjz = riz - dz;
  // Velocity of j's contact point against i's: v + w x r on each side.
  const double vcx = (j.vx + (j.wy * rjz - j.wz * rjy)) - (i.vx + (i.wy * riz - i.wz * riy));
  const double vcy = (j.vy + (j.wz * rjx - j.wx * rjz)) - (i.vy + (i.wz * rix - i.wx * riz));
  const double vcz = (j.vz + (j.wx * rjy - j.wy * rjx)) - (i.vz + (i.wx * riy - i.wy * rix));
  const double vn = vcx * nx + vcy * ny + vcz * nz;
  const double wrx = j.wx - i.wx;
  const double wry = j.wy - i.wy;
  const double wrz = j.wz - i.wz;
  const double wn = wrx * nx + wry * ny + wrz * nz;
  const double sx0 = b.sx[k];
  const double sy0 = b.sy[k];
  const double sz0 = b.sz[k];
  const double bx0 = b.bx[k];
  const double by0 = b.by[k];
  const double bz0 = b.bz[k];
  double sx = sx0;
  double sy = sy0;
  double sz = sz0;
  double bx = bx0;
  double by = by0;
  double bz = bz0;
  rotate_into_plane(sx, sy, sz, nx, ny, nz);
  rotate_into_plane(bx, by, bz, nx, ny, nz);
  // This step's increments: stiffness times the relative motion (tangential parts in-plane).
  const double fn0 = b.fn[k];
  const double twist0 = b.twist[k];
  const double fn = fn0 + -vn * s.normal_per_m;
  sx += -(vcx - vn * nx) * s.shear_per_m;
  sy += -(vcy - vn * ny) * s.shear_per_m;
  sz += -(vcz - vn * nz) * s.shear_per_m;
  const double twist = twist0 + -wn * s.twist_per_rad;
  bx += -(wrx - wn * nx) * s.bending_per_rad;
  by += -(wry - wn * ny) * s.bending_per_rad;
  bz += -(wrz - wn * nz) * s.bending_per_rad;
  // Signed criteria (bond_tensile_stress, bond_shear_stress): compression lowers the tensile
  // stress, it never breaks a bond alone. Each is "a norm times a factor exceeds what the rest
  // leaves", compared squared: -F/A + 2|M| R/J > sigma_c is 2|M| R/J > sigma_c + F/A, true
  // when the right side is negative, else when its square is exceeded (no square root).
  const double tensile_left = s.tensile_strength_Pa + fn * s.per_area;
  const double bending2 = (bx * bx + by * by + bz * bz) * (4.0 * s.rim_per_polar * s.rim_per_polar);
  const bool tensile_breaks = (tensile_left < 0.0) | (bending2 > tensile_left * tensile_left);
  const double shear_left = s.shear_strength_Pa - std::fabs(twist) * s.rim_per_polar;
  const double shear2 = (sx * sx + sy * sy + sz * sz) * (s.per_area * s.per_area);
  const bool shear_breaks = (shear_left < 0.0) | (shear2 > shear_left * shear_left);
  const bool breaks = tensile_breaks | shear_breaks;
  // The loads are advanced on the step a bond breaks (they are its last), not after.
  b.fn[k] = live ? fn : fn0;
  b.twist[k] = live ? twist : twist0;
  b.sx[k] = live ? sx : sx0;
  b.sy[k] = live ? sy : sy0;
  b.sz[k] = live ? sz : sz0;
  b.bx[k] = live ? bx : bx0;
  b.by[k] = live ? by : by0;
  b.bz[k] = live ? bz : bz0;
  b.broken[k] = (live & breaks) ? 1.0 : was_broken;
  b.out.carried[k] = (live & !breaks) ? 1.0 : 0.0;
  // On j: the normal force along n and the shear force; the moments about n and in-plane, and
  // each force's moment about its particle's centre.
  const double fx = fn * nx + sx;
  const double fy = fn * ny + sy;
  const double fz = fn * nz + sz;
  const double mx = twist * nx + bx;
  const double my = twist * ny + by;
  const double mz = twist * nz + bz;
  // Stored as the force on i (exact negation: the sums' bits are a force-on-j pass's).
  b.out.fx[k] = -fx;
  b.out.fy[k] = -fy;
  b.out.fz[k] = -fz;
  b.out.tj_x[k] = mx + (rjy * fz - rjz * fy);
  b.out.tj_y[k] = my + (rjz * fx - rjx * fz);
  b.out.tj_z[k] = mz + (rjx * fy - rjy * fx);
  b.out.ti_x[k] = -mx - (riy * fz - riz * fy);
  b.out.ti_y[k] = -my - (riz * fx - rix * fz);
  b.out.ti_z[k] = -mz - (rix * fy - riy * fx);
}

}  // namespace planter::dem::lanes
