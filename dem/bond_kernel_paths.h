#pragma once
// The bond step's paths, one function each (dem/bond_kernel.cpp chooses among them).
#include <cstddef>

#include "dem/bond_lane.h"

namespace planter::dem::lanes {

void bonds_scalar(const BondView& b, const MotionView& m, const BondStep& s, std::size_t n);
#if defined(__x86_64__)
void bonds_sse2(const BondView& b, const MotionView& m, const BondStep& s, std::size_t n);
void bonds_avx2(const BondView& b, const MotionView& m, const BondStep& s, std::size_t n);
void bonds_avx512(const BondView& b, const MotionView& m, const BondStep& s, std::size_t n);
#endif

}  // namespace planter::dem::lanes
