// The vector paths: one pair per lane (OpenMP's simd loop; built with -fopenmp-simd, no
// runtime). On x86-64 each is compiled for its instruction set and picked at run time by the
// CPU's flags; elsewhere the wider ones are the baseline's (host_runs never picks them).
#include "dem/bond_lane.h"
#include "dem/contact_lane.h"
#include "dem/lane_paths.h"

// Clang cannot vectorise the lanes under a sanitizer's instrumentation (the fuzz build) and
// says so as an error with -Werror; the loops are still right there, one lane at a time.
#if defined(__clang__)
#pragma clang diagnostic ignored "-Wpass-failed"
#endif

#if defined(__x86_64__)
#define PLANTER_DEM_TARGET(isa) [[gnu::target(isa)]]
#else
#define PLANTER_DEM_TARGET(isa)
#endif

namespace planter::dem::lanes {
namespace {

// One pair per lane over [begin, end), inlined into each path so that it is compiled for that
// path's instruction set.
template <auto Lane, typename View, typename Step>
[[gnu::always_inline]] inline void each_lane(const View& v, const MotionView& m, const Step& s,
                                             std::size_t begin, std::size_t end) {
#pragma omp simd
  for (std::size_t k = begin; k < end; ++k) Lane(v, m, s, k);
}

}  // namespace

void bonds_baseline(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                    std::size_t end) {
  each_lane<bond_lane>(b, m, s, begin, end);
}
PLANTER_DEM_TARGET("avx2")
void bonds_avx2(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                std::size_t end) {
  each_lane<bond_lane>(b, m, s, begin, end);
}
PLANTER_DEM_TARGET("avx512f")
void bonds_avx512(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                  std::size_t end) {
  each_lane<bond_lane>(b, m, s, begin, end);
}

void contacts_baseline(const ContactView& c, const MotionView& m, const ContactStep& s,
                       std::size_t begin, std::size_t end) {
  each_lane<contact_pair_lane>(c, m, s, begin, end);
}
PLANTER_DEM_TARGET("avx2")
void contacts_avx2(const ContactView& c, const MotionView& m, const ContactStep& s,
                   std::size_t begin, std::size_t end) {
  each_lane<contact_pair_lane>(c, m, s, begin, end);
}
PLANTER_DEM_TARGET("avx512f")
void contacts_avx512(const ContactView& c, const MotionView& m, const ContactStep& s,
                     std::size_t begin, std::size_t end) {
  each_lane<contact_pair_lane>(c, m, s, begin, end);
}

void platens_baseline(const PlatenView& c, const MotionView& m, const PlatenStep& s,
                      std::size_t begin, std::size_t end) {
  each_lane<platen_lane>(c, m, s, begin, end);
}
PLANTER_DEM_TARGET("avx2")
void platens_avx2(const PlatenView& c, const MotionView& m, const PlatenStep& s, std::size_t begin,
                  std::size_t end) {
  each_lane<platen_lane>(c, m, s, begin, end);
}
PLANTER_DEM_TARGET("avx512f")
void platens_avx512(const PlatenView& c, const MotionView& m, const PlatenStep& s,
                    std::size_t begin, std::size_t end) {
  each_lane<platen_lane>(c, m, s, begin, end);
}

}  // namespace planter::dem::lanes
