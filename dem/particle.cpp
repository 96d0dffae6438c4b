#include "dem/particle.h"

namespace planter::dem {

Particle make_particle(const Vec3& x, double radius_m, double density_kg_m3) {
  constexpr double kPi = 3.14159265358979323846;
  Particle p;
  p.x = x;
  p.radius_m = radius_m;
  p.mass_kg = density_kg_m3 * 4.0 / 3.0 * kPi * radius_m * radius_m * radius_m;
  p.inertia_kgm2 = 0.4 * p.mass_kg * radius_m * radius_m;
  return p;
}

}  // namespace planter::dem
