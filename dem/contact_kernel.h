#pragma once
// The Hertz-Mindlin step of every candidate pair at once, on a vector path
// (dem/vector_path.h).
#include "dem/bond_arrays.h"
#include "dem/contact_arrays.h"
#include "dem/vector_path.h"

namespace planter::dem {

// Evaluates every candidate pair's contact over one step from the particles' motion, carries
// its tangential spring, and leaves its loads in the arrays' outputs (add_contact_loads adds
// them). `friction` and `rolling_friction` are the particles' material's.
void update_contacts(VectorPath path, ContactArrays& contacts, const ParticleMotion& motion,
                     double friction, double rolling_friction, double dt);

}  // namespace planter::dem
