#pragma once
// The vector paths of the DEM's per-pair steps (bonds, contacts), chosen at run time from the
// CPU's flags, so that one build serves every x86-64 CPU. Every path computes the same
// arithmetic per pair, so all give bit-identical results; a test holds them to it on every
// path the host runs.
#include <string_view>

namespace planter::dem {

enum class VectorPath {
  kScalar,    // one pair at a time, the compiler's vectoriser off: the reference
  kBaseline,  // the target's own vectors: SSE2 on x86-64 (2 pairs a step), NEON on AArch64
  kAvx2,      // 4 pairs a step
  kAvx512,    // 8
};

[[nodiscard]] std::string_view name(VectorPath p);
// The widest path this CPU runs.
[[nodiscard]] VectorPath widest_vector_path();
[[nodiscard]] bool host_runs(VectorPath p);
// `p` if the host runs it, else the widest it does (never an illegal instruction).
[[nodiscard]] VectorPath runnable(VectorPath p);
// Whether the pair steps on path `p` read the particles' motion as rows (ParticleMotion::rows:
// the AVX-512 lanes' transposes), so that the other paths are spared copying them.
[[nodiscard]] constexpr bool reads_motion_rows(VectorPath p) { return p == VectorPath::kAvx512; }

// One function per path; pick() returns the one for a path the host runs.
template <typename Fn>
struct PathTable {
  Fn scalar, baseline, avx2, avx512;
  [[nodiscard]] Fn pick(VectorPath p) const {
    switch (runnable(p)) {
      case VectorPath::kBaseline:
        return baseline;
      case VectorPath::kAvx2:
        return avx2;
      case VectorPath::kAvx512:
        return avx512;
      case VectorPath::kScalar:
        break;
    }
    return scalar;
  }
};

}  // namespace planter::dem
