#pragma once
// Potyondy-Cundall parallel bond between two particles (EDEM's "Hertz-Mindlin with Bonding"):
// loads grow from zero when the bond forms, by stiffness per unit area times the relative
// motion, and the bond breaks on its signed tensile or its shear criterion.
#include "dem/material.h"
#include "dem/particle.h"

namespace planter::dem {

struct Bond {
  int i = 0;
  int j = 0;
  double normal_force_N = 0.0;         // along n (i -> j) on j; negative = tension
  Vec3 shear_force = Vec3::Zero();     // on j, in the contact plane
  double twist_moment = 0.0;           // about n, on j
  Vec3 bending_moment = Vec3::Zero();  // in the contact plane, on j
  bool broken = false;
  // The particles' overlap when the bond formed (the builder packs rings a radius apart). The
  // pair's Hertz contact counts overlap beyond it, so the as-built packing holds no stress.
  double rest_overlap_m = 0.0;
};

struct BondGeometry {
  double area_m2;     // A = pi R_B^2
  double polar_m4;    // J = pi R_B^4 / 2
  double bending_m4;  // I = J / 2
};
BondGeometry bond_geometry(double radius_m);

// Tensile and shear stress at the bond's rim now (the breakage criteria's left sides).
double bond_tensile_stress(const Bond& b, const BondParameters& p);
double bond_shear_stress(const Bond& b, const BondParameters& p);

// What every bond's step shares, worked out once a step instead of once a bond: the
// stiffnesses times the bond's section and dt, and the strengths.
struct BondStep {
  double normal_per_m;     // S_n A dt
  double shear_per_m;      // S_t A dt
  double twist_per_rad;    // S_t J dt
  double bending_per_rad;  // S_n I dt
  double per_area;         // 1 / A
  double rim_per_polar;    // R_B / J
  double tensile_strength_Pa;
  double shear_strength_Pa;
};
BondStep bond_step(const BondParameters& p, double dt);

// Advances the bond's loads over dt from the particles' current motion, checks breakage, and
// adds the loads to the particles' force and torque (nothing when broken). One bond on the
// reference path of dem/bond_kernel.h (a world steps all its bonds at once there).
void update_bond(Bond& b, const BondStep& s, Particle& pi, Particle& pj);
inline void update_bond(Bond& b, const BondParameters& p, Particle& pi, Particle& pj, double dt) {
  update_bond(b, bond_step(p, dt), pi, pj);
}

// Elastic energy stored in the bond (for the energy balance).
double bond_energy(const Bond& b, const BondParameters& p);

}  // namespace planter::dem
