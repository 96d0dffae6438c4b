#include "sim/dem/seedling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace planter::dem {

SeedlingBuild build_seedling(DemWorld& world, const SeedlingGeometry& g) {
  constexpr double kPi = 3.14159265358979323846;
  const double r = g.particle_radius_m;
  const double pitch = 2.0 * r;
  const int sections = std::max(1, static_cast<int>(std::floor((g.length_m - pitch) / pitch)) + 1);
  const double z0 = -0.5 * (sections - 1) * pitch;
  SeedlingBuild out;
  out.min_y_m = std::numeric_limits<double>::infinity();
  out.max_y_m = -out.min_y_m;
  for (int s = 0; s < sections; ++s) {
    const double z = z0 + s * pitch;
    for (int layer = 0; layer < g.layers; ++layer) {
      // Rings a particle radius apart inwards from the skin; the centre stays hollow.
      const double ring_m = 0.5 * g.diameter_m - r - layer * r;
      if (ring_m <= 0.0) break;
      const int count = std::max(3, static_cast<int>(std::lround(2.0 * kPi * ring_m / pitch)));
      const double step = 2.0 * kPi / count;
      const double turn = (s % 2 == 0 ? 0.0 : 0.5 * step) + layer * 0.5 * step;
      for (int k = 0; k < count; ++k) {
        const double a = turn + k * step;
        Vec3 x(ring_m * std::cos(a), ring_m * std::sin(a), z);
        if (g.curvature_radius_m > 0.0) {
          // Bend the axis on a circle of that radius in the YZ plane (the white part's curve).
          const double phi = z / g.curvature_radius_m;
          const double rr = g.curvature_radius_m + x.y();
          x = Vec3(x.x(), rr * std::cos(phi) - g.curvature_radius_m, rr * std::sin(phi));
        }
        world.add_particle(make_particle(x, r, g.density_kg_m3));
        out.min_y_m = std::min(out.min_y_m, x.y() - r);
        out.max_y_m = std::max(out.max_y_m, x.y() + r);
        ++out.particles;
      }
    }
  }
  out.bonds = world.bond_neighbours(g.bond_gap_m);
  return out;
}

}  // namespace planter::dem
