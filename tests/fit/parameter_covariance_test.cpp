// The fit's stated intervals hold the truth about as often as they claim, also when the
// residual is correlated from row to row (analysis/parameter_covariance.h).
#include "analysis/parameter_covariance.h"

#include <gtest/gtest.h>

#include <Eigen/SVD>
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

TEST(ParameterCovariance, AWeaklyDeterminedParameterBesideALargeOneReadsLargeNotZero) {
  // A draft in N beside a relaxation time the rows barely move: the second column is 1e-6 of the
  // first but for a small part of its own, and its scale is 1e-6 of the first's. Its SD, from
  // J's singular values (the independent-rows form, which white residuals give), is large; the
  // normal equations unscaled put that direction under the pseudo-inverse's threshold.
  constexpr Eigen::Index kRows = 2000;
  Eigen::MatrixXd jac(kRows, 2);
  Eigen::VectorXd residual(kRows);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (Eigen::Index i = 0; i < kRows; ++i) {
    const double t = static_cast<double>(i) / kRows;
    jac(i, 0) = 1e4 * (1.0 + t);
    jac(i, 1) = 1e-2 * (1.0 + t + 1e-4 * std::sin(37.0 * static_cast<double>(i)));
    residual(i) = noise(rng);
  }
  const double sigma2 = residual.squaredNorm() / static_cast<double>(kRows - 2);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jac, Eigen::ComputeThinV);
  double reference = 0.0;
  for (Eigen::Index k = 0; k < 2; ++k)
    reference += std::pow(svd.matrixV()(1, k) / svd.singularValues()(k), 2);
  reference = std::sqrt(sigma2 * reference);
  const double sd = std::sqrt(hac_covariance(jac, residual).covariance(1, 1));
  EXPECT_GT(reference, 1.0);  // the case is the weak one it means to be
  EXPECT_NEAR(sd / reference, 1.0, 0.2);
}

}  // namespace
}  // namespace planter::analysis
