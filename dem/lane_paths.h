#pragma once
// The per-pair steps' paths, one function each (dem/bond_kernel.cpp and dem/contact_kernel.cpp
// pick among them): the scalar reference in lanes_scalar.cpp, the vector ones in
// lanes_simd.cpp.
#include <cstddef>

#include "dem/lane_views.h"

namespace planter::dem::lanes {

using BondsFn = void (*)(const BondView&, const MotionView&, const BondStep&, std::size_t,
                         std::size_t);
using ContactsFn = void (*)(const ContactView&, const MotionView&, const ContactStep&, std::size_t,
                            std::size_t);
using PlatensFn = void (*)(const PlatenView&, const MotionView&, const PlatenStep&, std::size_t,
                           std::size_t);

void bonds_scalar(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                  std::size_t end);
void bonds_baseline(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                    std::size_t end);
void bonds_avx2(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                std::size_t end);
void bonds_avx512(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                  std::size_t end);

void contacts_scalar(const ContactView& c, const MotionView& m, const ContactStep& s,
                     std::size_t begin, std::size_t end);
void contacts_baseline(const ContactView& c, const MotionView& m, const ContactStep& s,
                       std::size_t begin, std::size_t end);
void contacts_avx2(const ContactView& c, const MotionView& m, const ContactStep& s,
                   std::size_t begin, std::size_t end);
void contacts_avx512(const ContactView& c, const MotionView& m, const ContactStep& s,
                     std::size_t begin, std::size_t end);

void platens_scalar(const PlatenView& c, const MotionView& m, const PlatenStep& s,
                    std::size_t begin, std::size_t end);
void platens_baseline(const PlatenView& c, const MotionView& m, const PlatenStep& s,
                      std::size_t begin, std::size_t end);
void platens_avx2(const PlatenView& c, const MotionView& m, const PlatenStep& s, std::size_t begin,
                  std::size_t end);
void platens_avx512(const PlatenView& c, const MotionView& m, const PlatenStep& s,
                    std::size_t begin, std::size_t end);

}  // namespace planter::dem::lanes
