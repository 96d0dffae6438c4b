// The vector paths: one bond per lane (OpenMP's simd loop; built with -fopenmp-simd, no
// runtime), each compiled for its instruction set and chosen at run time by the CPU's flags.
#include "dem/bond_kernel_paths.h"

namespace planter::dem::lanes {

#if defined(__x86_64__)
void bonds_sse2(const BondView& b, const MotionView& m, const BondStep& s, std::size_t n) {
#pragma omp simd
  for (std::size_t k = 0; k < n; ++k) bond_lane(b, m, s, k);
}

[[gnu::target("avx2")]] void bonds_avx2(const BondView& b, const MotionView& m, const BondStep& s,
                                        std::size_t n) {
#pragma omp simd
  for (std::size_t k = 0; k < n; ++k) bond_lane(b, m, s, k);
}

[[gnu::target("avx512f")]] void bonds_avx512(const BondView& b, const MotionView& m,
                                             const BondStep& s, std::size_t n) {
#pragma omp simd
  for (std::size_t k = 0; k < n; ++k) bond_lane(b, m, s, k);
}
#endif

}  // namespace planter::dem::lanes
