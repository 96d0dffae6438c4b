#pragma once
// The covariance of least-squares parameters whose residuals are not independent. A fitted
// channel's residual is correlated from row to row: the anti-alias filter smears the noise over
// neighbouring rows, and what the model leaves out is slow. sigma^2 (J'J)^-1 assumes
// independent rows and states intervals several times too narrow (issue 32: 11 of 38 hidden
// values inside their 95 % intervals). The sandwich form with a Bartlett-weighted long-run
// score covariance holds for correlated rows: Newey & West (1987), Econometrica 55(3), with the
// bandwidth chosen by Andrews' (1991, Econometrica 59(3)) AR(1) plug-in rule, here applied to the
// residual itself rather than to each score (a simplification: one bandwidth for all parameters).
#include <Eigen/Dense>
#include <cstddef>

namespace planter::analysis {

struct ParameterCovariance {
  Eigen::MatrixXd covariance;
  std::size_t bandwidth_rows = 0;  // the Bartlett window's half width (0: independent rows)
  double lag_one_correlation = 0.0;
};

// jac: rows x parameters, d prediction / d parameter at the solution; residual: prediction - y at
// the same rows, in order. Rows are taken as evenly spaced.
ParameterCovariance hac_covariance(const Eigen::MatrixXd& jac, const Eigen::VectorXd& residual);

}  // namespace planter::analysis
