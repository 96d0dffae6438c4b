#pragma once
// The step of every parallel bond, on the widest vector path the host has (chosen at run time:
// one build serves every x86-64 CPU) or on a named one. Every path computes the same
// arithmetic per bond (dem/bond_lane.h), so all give bit-identical loads; a test holds them to
// it on every path the host can run.
#include <string_view>

#include "dem/bond_arrays.h"

namespace planter::dem {

enum class VectorPath {
  kScalar,  // one bond at a time, the compiler's vectoriser off: the reference
  kSse2,    // 2 bonds a lane set (every x86-64 CPU)
  kAvx2,    // 4
  kAvx512,  // 8
};

[[nodiscard]] std::string_view name(VectorPath p);
// The widest path this CPU runs (kScalar off x86-64).
[[nodiscard]] VectorPath widest_vector_path();
[[nodiscard]] bool host_runs(VectorPath p);

// Advances every bond's loads over one step from the particles' motion, checks breakage, and
// leaves each bond's loads on its particles in the arrays' outputs (add_bond_loads adds them).
void update_bonds(VectorPath path, BondArrays& bonds, const ParticleMotion& motion,
                  const BondStep& step);

}  // namespace planter::dem
