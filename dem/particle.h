#pragma once
// One spherical particle of the bonded-particle model (SI units throughout).
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace planter::dem {

using Vec3 = Eigen::Vector3d;

struct Particle {
  Vec3 x = Vec3::Zero();    // position, m
  Vec3 v = Vec3::Zero();    // velocity, m/s
  Vec3 w = Vec3::Zero();    // angular velocity, rad/s
  Vec3 f = Vec3::Zero();    // force this step, N
  Vec3 tau = Vec3::Zero();  // torque this step, N*m
  double radius_m = 1.5e-3;
  double mass_kg = 1.23e-5;
  double inertia_kgm2 = 0.0;  // solid sphere: 2/5 m r^2
  bool fixed = false;         // held in place (a clamp, a platen particle)
};

// 1/|w| of an angular velocity, 0 when it does not spin: the rolling torque's direction is w
// times it (worked out once a step per particle, not once per contact).
inline double inverse_spin(const Vec3& w) {
  const double spin = w.norm();
  return spin > 0.0 ? 1.0 / spin : 0.0;
}

// A particle of the material's density and the given radius, at rest.
Particle make_particle(const Vec3& x, double radius_m, double density_kg_m3);

}  // namespace planter::dem
