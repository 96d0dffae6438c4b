// The fit's stated intervals hold the truth about as often as they claim, also when the
// residual is correlated from row to row (analysis/parameter_covariance.h).
#include "analysis/parameter_covariance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace planter::analysis {
namespace {

// A constant measured through AR(1) noise of lag-one correlation rho: the fit is the mean, the
// Jacobian a column of ones. Returns how often the 95 % interval holds the true value (0), and
// the mean ratio of the stated SD to the independent-rows SD.
struct Coverage {
  double rate = 0.0, widening = 0.0;
};
Coverage mean_through_ar1(double rho, int draws) {
  constexpr Eigen::Index kRows = 4000;
  Coverage c;
  for (int d = 0; d < draws; ++d) {
    std::mt19937 rng(static_cast<unsigned>(1000 + d));
    std::normal_distribution<double> innovation(0.0, 1.0);
    Eigen::VectorXd y(kRows);
    double v = innovation(rng) / std::sqrt(1.0 - rho * rho);
    for (Eigen::Index i = 0; i < kRows; ++i) {
      y(i) = v;
      v = rho * v + innovation(rng);
    }
    const double mean = y.mean();
    const Eigen::VectorXd residual = Eigen::VectorXd::Constant(kRows, mean) - y;
    const Eigen::MatrixXd jac = Eigen::MatrixXd::Ones(kRows, 1);
    const double sd = std::sqrt(hac_covariance(jac, residual).covariance(0, 0));
    const double independent =
        std::sqrt(residual.squaredNorm() / static_cast<double>(kRows - 1) / kRows);
    c.rate += std::abs(mean) <= 1.96 * sd ? 1.0 / draws : 0.0;
    c.widening += sd / independent / draws;
  }
  return c;
}

TEST(ParameterCovariance, WhiteResidualsGiveTheIndependentRowsForm) {
  const Coverage c = mean_through_ar1(0.0, 200);
  EXPECT_NEAR(c.widening, 1.0, 0.05);
  EXPECT_GT(c.rate, 0.90);
}

TEST(ParameterCovariance, CorrelatedResidualsWidenTheIntervalUntilItHoldsTheTruth) {
  // sigma^2 (J'J)^-1 would state an SD sqrt((1 - rho) / (1 + rho)) = 0.23 of the true one here
  // and hold the truth about 35 % of the time.
  const Coverage c = mean_through_ar1(0.9, 200);
  EXPECT_GT(c.widening, 3.5);
  EXPECT_GT(c.rate, 0.88);
  EXPECT_LT(c.rate, 0.99);
}

}  // namespace
}  // namespace planter::analysis
