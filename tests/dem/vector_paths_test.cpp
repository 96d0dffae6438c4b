// The bond and contact steps' vector paths give the scalar path's results bit for bit (issue 30): a
// compression fast enough to break bonds, run on every path this CPU has.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "dem/compression_test.h"

namespace planter::dem {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}

DemWorld crushed_on(VectorPath path, int steps, int threads = 1) {
  CompressionSetup s;
  // A platen at 33 mm/s: bonds start breaking after about 2500 steps (941 of 3216 by 3000).
  s.speedup = 1e4;
  CompressionWorld c = make_compression_world(s);
  c.world.set_vector_path(path);
  c.world.set_threads(threads);
  for (int k = 0; k < steps; ++k) c.world.step(s.time_step_s);
  return c.world;
}

// Particles (position, velocity, spin) and bonds (loads, state) that differ in any bit.
void expect_same_bits(const DemWorld& reference, const DemWorld& world, const std::string& what) {
  EXPECT_EQ(world.broken_bonds(), reference.broken_bonds()) << what;
  const auto& a = reference.particles();
  const auto& b = world.particles();
  ASSERT_EQ(a.size(), b.size());
  std::size_t differ = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!same_bits(a[k].x, b[k].x) || !same_bits(a[k].v, b[k].v) || !same_bits(a[k].w, b[k].w)) {
      ++differ;
    }
  }
  EXPECT_EQ(differ, 0u) << what << ": particles whose motion differs from the scalar path";
  const std::vector<Bond> ra = reference.bonds();
  const std::vector<Bond> rb = world.bonds();
  ASSERT_EQ(ra.size(), rb.size());
  std::size_t bonds_differ = 0;
  for (std::size_t k = 0; k < ra.size(); ++k) {
    if (!same_bits(ra[k].normal_force_N, rb[k].normal_force_N) ||
        !same_bits(ra[k].shear_force, rb[k].shear_force) ||
        !same_bits(ra[k].bending_moment, rb[k].bending_moment) ||
        !same_bits(ra[k].twist_moment, rb[k].twist_moment) || ra[k].broken != rb[k].broken) {
      ++bonds_differ;
    }
  }
  EXPECT_EQ(bonds_differ, 0u) << what << ": bonds whose loads differ";
}

constexpr int kSteps = 3000;

TEST(PairVectorPaths, EveryPathTheHostRunsMatchesTheScalarPathBitForBit) {
  const DemWorld reference = crushed_on(VectorPath::kScalar, kSteps);
  ASSERT_GT(reference.broken_bonds(), 0) << "the run should break bonds (the mask is tested)";
  ASSERT_LT(reference.broken_bonds(), static_cast<int>(reference.bonds().size()) / 2);
  int paths = 0;
  for (VectorPath path : {VectorPath::kBaseline, VectorPath::kAvx2, VectorPath::kAvx512}) {
    if (!host_runs(path)) continue;
    ++paths;
    expect_same_bits(reference, crushed_on(path, kSteps), std::string(name(path)));
  }
  EXPECT_GE(paths, 1);  // the baseline runs everywhere
}

TEST(PairVectorPaths, SharingTheStepBetweenThreadsChangesNoBit) {
  const DemWorld reference = crushed_on(VectorPath::kScalar, kSteps);
  for (int threads : {2, 3}) {
    expect_same_bits(reference, crushed_on(widest_vector_path(), kSteps, threads),
                     std::to_string(threads) + " threads");
  }
}

TEST(PairVectorPaths, TheWidestPathIsOneTheHostRuns) {
  EXPECT_TRUE(host_runs(widest_vector_path()));
  EXPECT_TRUE(host_runs(VectorPath::kScalar));
}

}  // namespace
}  // namespace planter::dem
