#include "dem/bond_kernel.h"

#include "dem/lane_paths.h"

namespace planter::dem {

void update_bonds(VectorPath path, BondArrays& bonds, const ParticleMotion& motion,
                  const BondStep& step, std::size_t begin, std::size_t end) {
  constexpr PathTable<lanes::BondsFn> kPaths{lanes::bonds_scalar, lanes::bonds_baseline,
                                             lanes::bonds_avx2, lanes::bonds_avx512};
  kPaths.pick(path)(lanes::view(bonds), lanes::view(motion), step, begin, end);
}

}  // namespace planter::dem
