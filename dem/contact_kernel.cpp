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

void update_platen_contacts(VectorPath path, PlatenArrays& platens, std::size_t platen,
                            const Vec3& point, const Vec3& normal, const Vec3& velocity,
                            const ParticleMotion& motion, double friction, double rolling_friction,
                            double dt, std::size_t begin, std::size_t end) {
  constexpr PathTable<lanes::PlatensFn> kPaths{lanes::platens_scalar, lanes::platens_baseline,
                                               lanes::platens_avx2, lanes::platens_avx512};
  const lanes::PlatenStep step{{friction, rolling_friction, dt},
                               point.x(),
                               point.y(),
                               point.z(),
                               normal.x(),
                               normal.y(),
                               normal.z(),
                               velocity.x(),
                               velocity.y(),
                               velocity.z()};
  kPaths.pick(path)(lanes::view(platens, platen), lanes::view(motion), step, begin, end);
}

}  // namespace planter::dem
