#pragma once
// Hertz-Mindlin (no slip) contact between two spheres with restitution damping, Coulomb
// friction on the tangential spring and EDEM type A rolling friction.
#include "dem/material.h"
#include "dem/particle.h"

namespace planter::dem {

// Effective values of a pair (or of a sphere and a wall: pass the wall as infinite radius/mass).
struct PairProperties {
  double e_star = 0.0;  // 1/E* = (1-v_i^2)/E_i + (1-v_j^2)/E_j
  double g_star = 0.0;  // 1/G* = 2(2-v_i)(1+v_i)/E_i + 2(2-v_j)(1+v_j)/E_j
  double r_star = 0.0;
  double m_star = 0.0;
  double beta = 0.0;  // ln e / sqrt(ln^2 e + pi^2)
  // sqrt(S_t / S_n) = sqrt(8 G* / (2 E*)): the tangential damping's root from the normal one.
  double shear_to_normal_root = 0.0;
};
PairProperties pair_properties(const ContactMaterial& m, double r_i, double r_j, double m_i,
                               double m_j);
// Two materials (a particle on the steel platen): elastic values from each, the interaction's
// restitution `e` (EDEM gives restitution and friction per material pair).
PairProperties pair_properties(const ContactMaterial& mat_i, const ContactMaterial& mat_j, double e,
                               double r_i, double r_j, double m_i, double m_j);

struct ContactResult {
  Vec3 force_on_i = Vec3::Zero();   // the force on particle i at the contact point
  Vec3 torque_on_i = Vec3::Zero();  // tangential + rolling torque on i
  Vec3 torque_on_j = Vec3::Zero();
  double normal_force_N = 0.0;  // elastic + damping, >= 0
  bool sliding = false;
};

// Elastic normal force at overlap d: 4/3 E* sqrt(R*) d^1.5 (the closed form the tests check).
double hertz_normal_force(const PairProperties& p, double overlap_m);
// Its potential: 8/15 E* sqrt(R*) d^2.5.
double hertz_energy(const PairProperties& p, double overlap_m);

// One contact evaluation. `tangential_spring` is the contact's history (the accumulated
// tangential displacement times stiffness), carried between steps by the caller. The overlap
// counts from `rest_overlap_m` (a bonded pair's as-built overlap; 0 for any other pair).
ContactResult hertz_mindlin(const ContactMaterial& m, const PairProperties& p, const Particle& i,
                            const Particle& j, double dt, Vec3& tangential_spring,
                            double rest_overlap_m = 0.0);

}  // namespace planter::dem
