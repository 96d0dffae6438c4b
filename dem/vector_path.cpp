#include "dem/vector_path.h"

namespace planter::dem {

std::string_view name(VectorPath p) {
  switch (p) {
    case VectorPath::kScalar:
      return "scalar";
    case VectorPath::kBaseline:
      return "baseline";
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
    case VectorPath::kBaseline:
      return true;
    case VectorPath::kAvx2:
      return __builtin_cpu_supports("avx2");
    case VectorPath::kAvx512:
      return __builtin_cpu_supports("avx512f");
  }
  return false;
#else
  return p == VectorPath::kScalar || p == VectorPath::kBaseline;
#endif
}

VectorPath widest_vector_path() {
  for (VectorPath p : {VectorPath::kAvx512, VectorPath::kAvx2, VectorPath::kBaseline}) {
    if (host_runs(p)) return p;
  }
  return VectorPath::kScalar;
}

VectorPath runnable(VectorPath p) { return host_runs(p) ? p : widest_vector_path(); }

}  // namespace planter::dem
