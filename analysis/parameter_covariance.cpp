#include "analysis/parameter_covariance.h"

#include <algorithm>
#include <cmath>

namespace planter::analysis {

ParameterCovariance hac_covariance(const Eigen::MatrixXd& jac, const Eigen::VectorXd& residual) {
  ParameterCovariance out;
  const Eigen::Index n = jac.rows(), p = jac.cols();
  out.covariance = Eigen::MatrixXd::Zero(p, p);
  if (p == 0 || n <= p) return out;
  // Andrews' rule for the Bartlett kernel: L = 1.1447 (alpha n)^(1/3), with
  // alpha = 4 rho^2 / ((1 - rho)^2 (1 + rho)^2) for an AR(1) of lag-one correlation rho.
  const double r0 = residual.squaredNorm();
  const double r1 = residual.head(n - 1).dot(residual.tail(n - 1));
  const double rho = r0 > 0 ? std::clamp(r1 / r0, -0.97, 0.97) : 0.0;
  const double alpha = 4.0 * rho * rho / ((1.0 - rho) * (1.0 - rho) * (1.0 + rho) * (1.0 + rho));
  const auto bandwidth = static_cast<Eigen::Index>(std::min(
      std::ceil(1.1447 * std::cbrt(alpha * static_cast<double>(n))), static_cast<double>(n / 2)));
  out.lag_one_correlation = rho;
  out.bandwidth_rows = static_cast<std::size_t>(bandwidth);
  // Scores g_i = J_i' e_i; S = sum over lags |l| <= L of (1 - |l|/(L+1)) sum_i g_i g_{i+l}'.
  const Eigen::MatrixXd g = jac.array().colwise() * residual.array();
  Eigen::MatrixXd s = g.transpose() * g;
  for (Eigen::Index l = 1; l <= bandwidth; ++l) {
    const double w = 1.0 - static_cast<double>(l) / static_cast<double>(bandwidth + 1);
    const Eigen::MatrixXd gamma = g.topRows(n - l).transpose() * g.bottomRows(n - l);
    s += w * (gamma + gamma.transpose());
  }
  // J'J inverted with its columns scaled to a norm of 1 (the covariance is the same in exact
  // arithmetic): columns whose norms span ten decades (a draft in N beside a relaxation time
  // the rows barely move) would otherwise put a weakly determined direction under the
  // pseudo-inverse's rank threshold, and its variance would read 0 instead of large.
  Eigen::VectorXd unscale(p);
  for (Eigen::Index c = 0; c < p; ++c) {
    const double norm = jac.col(c).norm();
    unscale(c) = norm > 0.0 ? 1.0 / norm : 1.0;
  }
  const Eigen::MatrixXd scaled = jac * unscale.asDiagonal();
  const Eigen::MatrixXd a_inv =
      (scaled.transpose() * scaled).completeOrthogonalDecomposition().pseudoInverse();
  const Eigen::MatrixXd s_scaled = unscale.asDiagonal() * s * unscale.asDiagonal();
  // Degrees of freedom as in the independent form, so white residuals give sigma^2 (J'J)^-1.
  out.covariance = static_cast<double>(n) / static_cast<double>(n - p) * unscale.asDiagonal() *
                   (a_inv * s_scaled * a_inv) * unscale.asDiagonal();
  return out;
}

}  // namespace planter::analysis
