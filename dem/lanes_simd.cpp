// The vector paths: one pair per lane (OpenMP's simd loop; built with -fopenmp-simd, no
// runtime). On x86-64 each is compiled for its instruction set and picked at run time by the
// CPU's flags; elsewhere the wider ones are the baseline's (host_runs never picks them).
#include <algorithm>
#include <utility>

#include "dem/bond_lane.h"
#include "dem/contact_lane.h"
#include "dem/lane_paths.h"
#include "dem/particle_motion.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

// GCC 12 warns that the intrinsics' deliberately undefined vectors (_mm512_undefined_pd, the
// unused half of a shuffle's source) may be used uninitialised: a false positive of its own
// headers.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

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

// One pair per lane over [begin, end), each lane reading its two particles from the motion's
// arrays by index; inlined into each path so that it is compiled for that path's instruction
// set.
template <auto Lane, typename View, typename Step>
[[gnu::always_inline]] inline void each_pair(const View& v, const MotionView& m, const Step& s,
                                             std::size_t begin, std::size_t end) {
#pragma omp simd
  for (std::size_t k = begin; k < end; ++k) {
    Lane(v, sphere_of(m, static_cast<std::size_t>(v.i[k])),
         sphere_of(m, static_cast<std::size_t>(v.j[k])), s, k);
  }
}

// One particle per lane over [begin, end) (the platens).
template <auto Lane, typename View, typename Step>
[[gnu::always_inline]] inline void each_lane(const View& v, const MotionView& m, const Step& s,
                                             std::size_t begin, std::size_t end) {
#pragma omp simd
  for (std::size_t k = begin; k < end; ++k) Lane(v, m, s, k);
}

#if defined(__x86_64__)
// The spheres of a block of pairs' particles, a column per quantity, for the AVX-512 path.
// Each lane reading its particles by index took a load and a shuffle into the vector for each
// of a pair's 22 values; here eight particles' rows (ParticleMotion::rows) are loaded whole and
// transposed into columns, which the lanes then read as whole vectors. The values are copied,
// not computed: the results' bits are the other paths'.
struct SphereColumns {
  static constexpr std::size_t kRows = 64;
  // column[v][q]: value v of a particle's row (ParticleMotion::rows' order) for pair q.
  alignas(64) double column[ParticleMotion::kRowValues][kRows];

  // A row's values are a Sphere's fields in order.
  static_assert(sizeof(Sphere) == ParticleMotion::kRowValues * sizeof(double));
  [[gnu::always_inline]] Sphere at(std::size_t q) const {
    return {column[0][q], column[1][q], column[2][q], column[3][q], column[4][q], column[5][q],
            column[6][q], column[7][q], column[8][q], column[9][q], column[10][q]};
  }
};

// Columns c[0..7] of the 8x8 block whose rows are particles p[0..7]'s values [half, half + 8):
// an unpack, then two rounds of 128-bit lane shuffles.
PLANTER_DEM_TARGET("avx512f")
[[gnu::always_inline]] inline void transposed(const double* rows, const int* p, std::size_t half,
                                              __m512d* c) {
  constexpr std::size_t w = ParticleMotion::kRowWidth;
  __m512d r[8];
  for (std::size_t l = 0; l < 8; ++l) {
    r[l] = _mm512_loadu_pd(rows + static_cast<std::size_t>(p[l]) * w + half);
  }
  const __m512d t0 = _mm512_unpacklo_pd(r[0], r[1]);
  const __m512d t1 = _mm512_unpackhi_pd(r[0], r[1]);
  const __m512d t2 = _mm512_unpacklo_pd(r[2], r[3]);
  const __m512d t3 = _mm512_unpackhi_pd(r[2], r[3]);
  const __m512d t4 = _mm512_unpacklo_pd(r[4], r[5]);
  const __m512d t5 = _mm512_unpackhi_pd(r[4], r[5]);
  const __m512d t6 = _mm512_unpacklo_pd(r[6], r[7]);
  const __m512d t7 = _mm512_unpackhi_pd(r[6], r[7]);
  const __m512d u0 = _mm512_shuffle_f64x2(t0, t2, 0x88);
  const __m512d u1 = _mm512_shuffle_f64x2(t0, t2, 0xDD);
  const __m512d u2 = _mm512_shuffle_f64x2(t1, t3, 0x88);
  const __m512d u3 = _mm512_shuffle_f64x2(t1, t3, 0xDD);
  const __m512d u4 = _mm512_shuffle_f64x2(t4, t6, 0x88);
  const __m512d u5 = _mm512_shuffle_f64x2(t4, t6, 0xDD);
  const __m512d u6 = _mm512_shuffle_f64x2(t5, t7, 0x88);
  const __m512d u7 = _mm512_shuffle_f64x2(t5, t7, 0xDD);
  c[0] = _mm512_shuffle_f64x2(u0, u4, 0x88);
  c[4] = _mm512_shuffle_f64x2(u0, u4, 0xDD);
  c[2] = _mm512_shuffle_f64x2(u1, u5, 0x88);
  c[6] = _mm512_shuffle_f64x2(u1, u5, 0xDD);
  c[1] = _mm512_shuffle_f64x2(u2, u6, 0x88);
  c[5] = _mm512_shuffle_f64x2(u2, u6, 0xDD);
  c[3] = _mm512_shuffle_f64x2(u3, u7, 0x88);
  c[7] = _mm512_shuffle_f64x2(u3, u7, 0xDD);
}

// Rows q..q+7 of `to` from the particles p[0..7].
PLANTER_DEM_TARGET("avx512f")
[[gnu::always_inline]] inline void transpose_eight(const double* rows, const int* p, std::size_t q,
                                                   SphereColumns& to) {
  __m512d c[8];
  transposed(rows, p, 0, c);
  for (std::size_t v = 0; v < 8; ++v) _mm512_store_pd(to.column[v] + q, c[v]);
  transposed(rows, p, 8, c);
  for (std::size_t v = 8; v < ParticleMotion::kRowValues; ++v) {
    _mm512_store_pd(to.column[v] + q, c[v - 8]);
  }
}

// each_pair on AVX-512, a block of pairs at a time: their spheres transposed into columns
// eight by eight (the block's last few one by one), then one pair per lane.
template <auto Lane, typename View, typename Step>
PLANTER_DEM_TARGET("avx512f")
[[gnu::always_inline]] inline void each_pair_transposed(const View& v, const MotionView& m,
                                                        const Step& s, std::size_t begin,
                                                        std::size_t end) {
  SphereColumns i;
  SphereColumns j;
  constexpr std::size_t w = ParticleMotion::kRowWidth;
  for (std::size_t first = begin; first < end; first += SphereColumns::kRows) {
    const std::size_t n = std::min(SphereColumns::kRows, end - first);
    std::size_t q = 0;
    for (; q + 8 <= n; q += 8) {
      transpose_eight(m.rows, v.i + first + q, q, i);
      transpose_eight(m.rows, v.j + first + q, q, j);
    }
    for (; q < n; ++q) {
      for (auto [to, p] : {std::pair{&i, v.i[first + q]}, std::pair{&j, v.j[first + q]}}) {
        const double* row = m.rows + static_cast<std::size_t>(p) * w;
        for (std::size_t value = 0; value < ParticleMotion::kRowValues; ++value) {
          to->column[value][q] = row[value];
        }
      }
    }
#pragma omp simd
    for (std::size_t k = 0; k < n; ++k) Lane(v, i.at(k), j.at(k), s, first + k);
  }
}
#endif

}  // namespace

void bonds_baseline(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                    std::size_t end) {
  each_pair<bond_lane>(b, m, s, begin, end);
}
PLANTER_DEM_TARGET("avx2")
void bonds_avx2(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                std::size_t end) {
  each_pair<bond_lane>(b, m, s, begin, end);
}
PLANTER_DEM_TARGET("avx512f")
void bonds_avx512(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                  std::size_t end) {
#if defined(__x86_64__)
  each_pair_transposed<bond_lane>(b, m, s, begin, end);
#else
  each_pair<bond_lane>(b, m, s, begin, end);
#endif
}

void contacts_baseline(const ContactView& c, const MotionView& m, const ContactStep& s,
                       std::size_t begin, std::size_t end) {
  each_pair<contact_pair_lane>(c, m, s, begin, end);
}
PLANTER_DEM_TARGET("avx2")
void contacts_avx2(const ContactView& c, const MotionView& m, const ContactStep& s,
                   std::size_t begin, std::size_t end) {
  each_pair<contact_pair_lane>(c, m, s, begin, end);
}
PLANTER_DEM_TARGET("avx512f")
void contacts_avx512(const ContactView& c, const MotionView& m, const ContactStep& s,
                     std::size_t begin, std::size_t end) {
#if defined(__x86_64__)
  each_pair_transposed<contact_pair_lane>(c, m, s, begin, end);
#else
  each_pair<contact_pair_lane>(c, m, s, begin, end);
#endif
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
