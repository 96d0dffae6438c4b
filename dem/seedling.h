#pragma once
// The paper's seedling: the clamped white part as a hollow double-layer cylinder of bonded
// spheres, built by the "spatial coordinate method": one cross-section of particles on
// concentric rings in the XY plane, copied along Z (the growth direction) every particle
// diameter, alternate copies turned by half a step so that the wall interlocks.
#include "dem/dem_world.h"

namespace planter::dem {

struct SeedlingGeometry {
  double length_m = 0.190;
  double diameter_m = 0.010;
  double particle_radius_m = 1.5e-3;
  int layers = 2;  // concentric rings in the wall
  double density_kg_m3 = 870.0;
  double bond_gap_m = 0.5e-3;       // pairs within 2r + gap are bonded
  double curvature_radius_m = 0.0;  // bend the axis in the YZ plane; 0 = straight
};

struct SeedlingBuild {
  int particles = 0;
  int bonds = 0;
  double min_y_m = 0.0;  // lowest and highest particle surface (where the platens start)
  double max_y_m = 0.0;
};

// How many particles build_seedling makes, without making them: what a run will cost is known
// before any memory is taken.
long seedling_particle_count(const SeedlingGeometry& g);

// Adds the seedling to `world` (centred on the origin, axis along Z) and bonds it.
SeedlingBuild build_seedling(DemWorld& world, const SeedlingGeometry& g);

}  // namespace planter::dem
