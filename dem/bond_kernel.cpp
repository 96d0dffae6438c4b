#include "dem/bond_kernel.h"

#include "dem/bond_kernel_paths.h"

namespace planter::dem {

std::string_view name(VectorPath p) {
  switch (p) {
    case VectorPath::kScalar:
      return "scalar";
    case VectorPath::kSse2:
      return "sse2";
    case VectorPath::kAvx2:
      return "avx2";
    case VectorPath::kAvx512:
      return "avx512";
  }
  return "scalar";
}

bool host_runs(VectorPath p) {
#if defined(__x86_64__)
  switch (p) {
    case VectorPath::kScalar:
    case VectorPath::kSse2:
      return true;
    case VectorPath::kAvx2:
      return __builtin_cpu_supports("avx2");
    case VectorPath::kAvx512:
      return __builtin_cpu_supports("avx512f");
  }
  return false;
#else
  return p == VectorPath::kScalar;
#endif
}

VectorPath widest_vector_path() {
  for (VectorPath p : {VectorPath::kAvx512, VectorPath::kAvx2, VectorPath::kSse2}) {
    if (host_runs(p)) return p;
  }
  return VectorPath::kScalar;
}

void update_bonds(VectorPath path, BondArrays& bonds, const ParticleMotion& motion,
                  const BondStep& step) {
  const lanes::BondView b = lanes::view(bonds);
  const lanes::MotionView m = lanes::view(motion);
  const std::size_t n = bonds.size();
#if defined(__x86_64__)
  // A path the host cannot run falls back to the widest it can (never an illegal instruction).
  const VectorPath run = host_runs(path) ? path : widest_vector_path();
  switch (run) {
    case VectorPath::kAvx512:
      return lanes::bonds_avx512(b, m, step, n);
    case VectorPath::kAvx2:
      return lanes::bonds_avx2(b, m, step, n);
    case VectorPath::kSse2:
      return lanes::bonds_sse2(b, m, step, n);
    case VectorPath::kScalar:
      break;
  }
#endif
  lanes::bonds_scalar(b, m, step, n);
}

}  // namespace planter::dem
