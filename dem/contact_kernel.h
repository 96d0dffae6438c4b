#pragma once
// The Hertz-Mindlin step of every candidate pair at once, on a vector path
// (dem/vector_path.h).
#include <cstddef>

#include "dem/contact_arrays.h"
#include "dem/particle_motion.h"
#include "dem/platen_arrays.h"
#include "dem/vector_path.h"

namespace planter::dem {

// Evaluates the contacts of candidate pairs [begin, end) over one step from the particles'
// motion, carries their tangential springs, and leaves their loads in the arrays' outputs
// (add_contact_loads adds them). `friction` and `rolling_friction` are the particles'
// material's. Each pair writes only its own entries: ranges may run at once.
void update_contacts(VectorPath path, ContactArrays& contacts, const ParticleMotion& motion,
                     double friction, double rolling_friction, double dt, std::size_t begin,
                     std::size_t end);

// Evaluates particles [begin, end) against platen `platen` (a point on it, its unit normal
// towards the particles, its velocity) over one step, carries the springs, and leaves the loads
// in the arrays (the particle adds them after its pairs'). `friction` and `rolling_friction` are
// the platen material's. Each particle writes only its own entries: ranges may run at once.
void update_platen_contacts(VectorPath path, PlatenArrays& platens, std::size_t platen,
                            const Vec3& point, const Vec3& normal, const Vec3& velocity,
                            const ParticleMotion& motion, double friction, double rolling_friction,
                            double dt, std::size_t begin, std::size_t end);

}  // namespace planter::dem
