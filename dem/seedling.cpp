#include "dem/seedling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace planter::dem {

namespace {

// Cross-sections along the axis, one every particle diameter.
int section_count(const SeedlingGeometry& g) {
  const double pitch = 2.0 * g.particle_radius_m;
  return std::max(1, static_cast<int>(std::floor((g.length_m - pitch) / pitch)) + 1);
}

// Rings a particle radius apart inwards from the skin; the centre stays hollow.
double ring_radius_m(const SeedlingGeometry& g, int layer) {
  return 0.5 * g.diameter_m - g.particle_radius_m - layer * g.particle_radius_m;
}

int ring_count(const SeedlingGeometry& g, double ring_m) {
  return std::max(3, static_cast<int>(std::lround(2.0 * std::numbers::pi * ring_m /
                                                  (2.0 * g.particle_radius_m))));
}
}  // namespace

long seedling_particle_count(const SeedlingGeometry& g) {
  long per_section = 0;
  for (int layer = 0; layer < g.layers; ++layer) {
    const double ring_m = ring_radius_m(g, layer);
    if (ring_m <= 0.0) break;
    per_section += ring_count(g, ring_m);
  }
  return per_section * section_count(g);
}

SeedlingBuild build_seedling(DemWorld& world, const SeedlingGeometry& g) {
  const double r = g.particle_radius_m;
  const double pitch = 2.0 * r;
  const int sections = section_count(g);
  const double z0 = -0.5 * (sections - 1) * pitch;
  SeedlingBuild out;
  out.min_y_m = std::numeric_limits<double>::infinity();
  out.max_y_m = -out.min_y_m;
  for (int s = 0; s < sections; ++s) {
    const double z = z0 + s * pitch;
    for (int layer = 0; layer < g.layers; ++layer) {
      const double ring_m = ring_radius_m(g, layer);
      if (ring_m <= 0.0) break;
      const int count = ring_count(g, ring_m);
      const double step = 2.0 * std::numbers::pi / count;
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
