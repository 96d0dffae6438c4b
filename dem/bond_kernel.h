#pragma once
// The step of every parallel bond at once, on a vector path (dem/vector_path.h).
#include <cstddef>

#include "dem/bond_arrays.h"
#include "dem/particle_motion.h"
#include "dem/vector_path.h"

namespace planter::dem {

// Advances the loads of bonds [begin, end) over one step from the particles' motion, checks
// breakage, and leaves each bond's loads on its particles in the arrays' outputs
// (add_bond_loads adds them). Each bond writes only its own entries: ranges may run at once.
void update_bonds(VectorPath path, BondArrays& bonds, const ParticleMotion& motion,
                  const BondStep& step, std::size_t begin, std::size_t end);

}  // namespace planter::dem
