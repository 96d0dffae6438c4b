#pragma once
// The step of every parallel bond at once, on a vector path (dem/vector_path.h).
#include "dem/bond_arrays.h"
#include "dem/vector_path.h"

namespace planter::dem {

// Advances every bond's loads over one step from the particles' motion, checks breakage, and
// leaves each bond's loads on its particles in the arrays' outputs (add_bond_loads adds them).
void update_bonds(VectorPath path, BondArrays& bonds, const ParticleMotion& motion,
                  const BondStep& step);

}  // namespace planter::dem
