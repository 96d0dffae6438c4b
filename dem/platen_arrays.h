#pragma once
// The particles' contacts with the platens as a structure of arrays (one particle per vector
// lane in dem/contact_kernel.h): each particle's Hertz-Mindlin constants against the platen
// material, and per platen and particle its tangential spring and this step's loads.
#include <cstddef>
#include <vector>

#include "dem/hertz_mindlin.h"
#include "dem/pair_property_columns.h"

namespace planter::dem {

struct PlatenArrays {
  std::size_t particles = 0;
  PairPropertyColumns constants;  // [particle]: PairProperties against the platen material
  // [platen * particles + particle]: the tangential spring (history), kept across rebuilds.
  std::vector<double> spring_x, spring_y, spring_z;
  // [platen * particles + particle], this step's: the force and torque on the particle, the
  // normal force, and whether the particle was within its radius of the platen (1) or not (0).
  std::vector<double> fx, fy, fz, tx, ty, tz, normal_N, near;

  // Sized for `platens` platens and `properties.size()` particles, the properties set, the
  // springs of the platens and particles already there kept (new ones at rest).
  void resize(std::size_t platens, const std::vector<PairProperties>& properties);
};

}  // namespace planter::dem
