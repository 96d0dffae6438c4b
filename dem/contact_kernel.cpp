#include "dem/contact_kernel.h"

#include "dem/lane_paths.h"

namespace planter::dem {

void update_contacts(VectorPath path, ContactArrays& contacts, const ParticleMotion& motion,
                     double friction, double rolling_friction, double dt, std::size_t begin,
                     std::size_t end) {
  constexpr PathTable<lanes::ContactsFn> kPaths{lanes::contacts_scalar, lanes::contacts_baseline,
                                                lanes::contacts_avx2, lanes::contacts_avx512};
  const lanes::ContactStep step{friction, rolling_friction, dt};
  kPaths.pick(path)(lanes::view(contacts), lanes::view(motion), step, begin, end);
}

}  // namespace planter::dem
