// The draft channel's kept factors are the opener draft law's own values, whichever arguments
// came before (analysis/draft_factors.h): a fit alternates between a base point and its steps.
#include "analysis/draft_factors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sim/soil/opener_draft.h"

namespace planter::analysis {
namespace {

struct Row {
  std::vector<double> t_s, v_mps, depth_mm;
  std::vector<bool> rest;
};

// Two seconds at 100 Hz: standing, then moving at a speed that wanders, the opener going down.
Row a_row(double speed_mps) {
  Row r;
  for (int k = 0; k < 200; ++k) {
    r.t_s.push_back(0.01 * k);
    r.rest.push_back(k < 40);
    r.v_mps.push_back(speed_mps * (1.0 + 0.1 * std::sin(0.05 * k)));
    r.depth_mm.push_back(k < 20 ? -5.0 : 0.6 * (k - 20));
  }
  return r;
}

// The share by the law's one-step form, row by row, as the plant steps it.
std::vector<double> share_by_the_law(const soil::OpenerDraftLaw& law, const Row& r) {
  std::vector<double> out(r.t_s.size(), 0.0);
  for (std::size_t k = 1; k < out.size(); ++k) {
    const double v = r.rest[k] ? 0.0 : r.v_mps[k], v_prev = r.rest[k - 1] ? 0.0 : r.v_mps[k - 1];
    const double dt = r.t_s[k] - r.t_s[k - 1];
    out[k] = soil::mobilised_share(law, out[k - 1], 0.5 * (v + v_prev) * dt, dt);
  }
  return out;
}

TEST(DraftFactors, KeptSharesAreTheLawsForEachArgument) {
  const Row slow = a_row(0.3), fast = a_row(0.9);
  soil::OpenerDraftLaw stiff, longer, loose;  // a step in the travel alone, then in both
  longer.mobilisation_mm = 40.0;
  loose.mobilisation_mm = 40.0;
  loose.rest_relaxation_s = 5.0;
  // A base, a step, the base again, another step, a third: each against the law.
  for (const auto& [law, row] :
       {std::pair{&stiff, &slow}, std::pair{&longer, &slow}, std::pair{&loose, &slow},
        std::pair{&stiff, &slow}, std::pair{&stiff, &fast}, std::pair{&loose, &fast},
        std::pair{&stiff, &slow}}) {
    const std::vector<double> expected = share_by_the_law(*law, *row);
    const std::vector<double>& got = draft_share_along(law->mobilisation_mm, law->rest_relaxation_s,
                                                       row->v_mps, row->rest, row->t_s);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t k = 0; k < got.size(); ++k) EXPECT_DOUBLE_EQ(got[k], expected[k]) << k;
  }
  EXPECT_EQ(share_by_the_law(stiff, slow)[30], 0.0);  // standing: nothing mobilised
  EXPECT_GT(share_by_the_law(stiff, slow).back(), 0.5);
}

TEST(DraftFactors, KeptDepthPowersAreTheLawsForEachArgument) {
  const Row row = a_row(0.5);
  const std::vector<double> deeper = [&] {
    std::vector<double> d = row.depth_mm;
    for (double& v : d) v += 10.0;
    return d;
  }();
  for (const auto& [depth, m] :
       {std::pair{&row.depth_mm, 1.0}, std::pair{&row.depth_mm, 1.7}, std::pair{&row.depth_mm, 1.0},
        std::pair{&deeper, 1.7}, std::pair{&row.depth_mm, 1.7}}) {
    const std::vector<double>& got = draft_depth_along(*depth, m);
    ASSERT_EQ(got.size(), depth->size());
    for (std::size_t k = 0; k < got.size(); ++k)
      EXPECT_NEAR(got[k], soil::draft_depth_cm((*depth)[k], m), 1e-12 * (1.0 + got[k])) << k;
  }
  EXPECT_EQ(draft_depth_along(row.depth_mm, 1.3)[0], 0.0);  // above the surface: no draft
}

}  // namespace
}  // namespace planter::analysis
