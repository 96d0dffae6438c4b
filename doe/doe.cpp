#include "doe/doe.h"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>
#include <limits>

namespace planter::doe {
namespace {

double f_upper_tail(double f, int df1, int df2) {
  if (df1 <= 0 || df2 <= 0 || !std::isfinite(f)) return f > 0.0 ? 0.0 : 1.0;
  if (f <= 0.0) return 1.0;
  const boost::math::fisher_f dist(df1, df2);
  return boost::math::cdf(boost::math::complement(dist, f));
}

Eigen::MatrixXd quadratic_terms(const Eigen::MatrixXd& x) {
  Eigen::MatrixXd m(x.rows(), 10);
  for (Eigen::Index r = 0; r < x.rows(); ++r) {
    const double a = x(r, 0), b = x(r, 1), c = x(r, 2);
    m.row(r) << 1, a, b, c, a * b, a * c, b * c, a * a, b * b, c * c;
  }
  return m;
}

// Least squares with the ANOVA of every column but the first (the intercept).
Anova analyse(const Eigen::MatrixXd& m, const Eigen::VectorXd& y,
              const std::vector<std::string>& term_names) {
  Anova a;
  const Eigen::Index n = m.rows(), p = m.cols();
  const Eigen::MatrixXd xtx = m.transpose() * m;
  const Eigen::MatrixXd xtx_inv = xtx.completeOrthogonalDecomposition().pseudoInverse();
  a.beta = xtx_inv * m.transpose() * y;
  a.intercept = a.beta(0);
  const Eigen::VectorXd fitted = m * a.beta;
  const double mean = y.mean();
  a.residual_ss = (y - fitted).squaredNorm();
  a.model_ss = (fitted.array() - mean).matrix().squaredNorm();
  a.model_df = static_cast<int>(p - 1);
  a.residual_df = static_cast<int>(n - p);
  const double total_ss = (y.array() - mean).matrix().squaredNorm();
  const double mse = a.residual_df > 0 ? a.residual_ss / a.residual_df : 0.0;
  // A fit with no residual left (or a deterministic surface the terms capture exactly) has
  // an unbounded F; p is then 0 only where the term carries any sum of squares.
  const double mse_floor = std::max(mse, 1e-300);
  a.model_f = a.model_df > 0 ? (a.model_ss / a.model_df) / mse_floor : 0.0;
  a.model_p = f_upper_tail(a.model_f, a.model_df, a.residual_df);
  a.r2 = total_ss > 0 ? 1.0 - a.residual_ss / total_ss : 0.0;
  a.r2_adjusted =
      total_ss > 0 && a.residual_df > 0
          ? 1.0 - (a.residual_ss / a.residual_df) / (total_ss / static_cast<double>(n - 1))
          : 0.0;
  for (Eigen::Index k = 1; k < p; ++k) {
    TermTest t;
    t.name = term_names[static_cast<std::size_t>(k - 1)];
    t.coefficient = a.beta(k);
    t.sum_of_squares = xtx_inv(k, k) > 0 ? a.beta(k) * a.beta(k) / xtx_inv(k, k) : 0.0;
    t.f_value = t.sum_of_squares / mse_floor;
    t.p_value = f_upper_tail(t.f_value, 1, a.residual_df);
    a.terms.push_back(t);
  }
  // Adequate precision (signal to noise): the range of the predicted values over the mean
  // standard error of prediction, sqrt(p * MSE / n).
  const double se = std::sqrt(static_cast<double>(p) * mse / static_cast<double>(n));
  a.adequate_precision = se > 0 ? (fitted.maxCoeff() - fitted.minCoeff()) / se
                                : std::numeric_limits<double>::infinity();
  return a;
}

}  // namespace

Eigen::MatrixXd plackett_burman_12(int factors) {
  static const int kGenerator[11] = {1, 1, -1, 1, 1, 1, -1, -1, -1, 1, -1};
  Eigen::MatrixXd d(12, factors);
  for (int r = 0; r < 11; ++r) {
    for (int c = 0; c < factors; ++c) d(r, c) = kGenerator[(c - r + 11) % 11];
  }
  d.row(11).setConstant(-1.0);
  return d;
}

Eigen::MatrixXd box_behnken_3(int centre_points) {
  Eigen::MatrixXd d(12 + centre_points, 3);
  d.setZero();
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  int r = 0;
  for (const auto& pr : pairs) {
    for (int sa : {-1, 1}) {
      for (int sb : {-1, 1}) {
        d(r, pr[0]) = sa;
        d(r, pr[1]) = sb;
        ++r;
      }
    }
  }
  return d;
}

Anova fit_main_effects(const Eigen::MatrixXd& coded, const Eigen::VectorXd& y,
                       const std::vector<std::string>& names) {
  Eigen::MatrixXd m(coded.rows(), coded.cols() + 1);
  m.col(0).setOnes();
  m.rightCols(coded.cols()) = coded;
  return analyse(m, y, names);
}

Anova fit_quadratic_3(const Eigen::MatrixXd& coded, const Eigen::VectorXd& y,
                      const std::vector<std::string>& n) {
  const std::vector<std::string> terms{n[0],        n[1],        n[2],
                                       n[0] + n[1], n[0] + n[2], n[1] + n[2],
                                       n[0] + "^2", n[1] + "^2", n[2] + "^2"};
  return analyse(quadratic_terms(coded), y, terms);
}

double predict_quadratic_3(const Anova& a, const Eigen::Vector3d& x) {
  Eigen::MatrixXd row = quadratic_terms(x.transpose());
  return (row * a.beta)(0);
}

Eigen::Vector3d solve_quadratic_3_for(const Anova& a, double target) {
  constexpr int kSteps = 40;
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  double best_err = std::numeric_limits<double>::infinity();
  double best_norm = 0.0;
  for (int i = 0; i <= kSteps; ++i) {
    for (int j = 0; j <= kSteps; ++j) {
      for (int k = 0; k <= kSteps; ++k) {
        const Eigen::Vector3d x(-1.0 + 2.0 * i / kSteps, -1.0 + 2.0 * j / kSteps,
                                -1.0 + 2.0 * k / kSteps);
        const double err = std::abs(predict_quadratic_3(a, x) - target);
        const double norm = x.squaredNorm();
        if (err < best_err - 1e-9 || (std::abs(err - best_err) <= 1e-9 && norm < best_norm)) {
          best = x;
          best_err = err;
          best_norm = norm;
        }
      }
    }
  }
  return best;
}

LackOfFit lack_of_fit(const Eigen::MatrixXd& coded, const Eigen::VectorXd& y, const Anova& a) {
  LackOfFit l;
  // Group the rows by their settings; the pure error is the spread within each group.
  std::vector<Eigen::Index> group(static_cast<std::size_t>(coded.rows()), -1);
  std::vector<Eigen::Index> first_rows;
  for (Eigen::Index r = 0; r < coded.rows(); ++r) {
    for (const Eigen::Index f : first_rows) {
      if ((coded.row(r) - coded.row(f)).cwiseAbs().maxCoeff() < 1e-9) {
        group[static_cast<std::size_t>(r)] = f;
        break;
      }
    }
    if (group[static_cast<std::size_t>(r)] < 0) {
      group[static_cast<std::size_t>(r)] = r;
      first_rows.push_back(r);
    }
  }
  for (const Eigen::Index f : first_rows) {
    double sum = 0.0;
    int n = 0;
    for (Eigen::Index r = 0; r < coded.rows(); ++r) {
      if (group[static_cast<std::size_t>(r)] == f) {
        sum += y(r);
        ++n;
      }
    }
    const double mean = sum / n;
    for (Eigen::Index r = 0; r < coded.rows(); ++r) {
      if (group[static_cast<std::size_t>(r)] == f) l.pure_error_ss += (y(r) - mean) * (y(r) - mean);
    }
    l.pure_error_df += n - 1;
  }
  const int distinct = static_cast<int>(first_rows.size());
  const int params = static_cast<int>(a.beta.size());
  l.df = distinct - params;
  l.available = l.pure_error_df > 0 && l.df > 0;
  if (!l.available) return l;
  l.ss = std::max(0.0, a.residual_ss - l.pure_error_ss);
  const double pure_ms = std::max(l.pure_error_ss / l.pure_error_df, 1e-300);
  l.f_value = (l.ss / l.df) / pure_ms;
  l.p_value = f_upper_tail(l.f_value, l.df, l.pure_error_df);
  return l;
}

double desirability(const Goal& g, double y) {
  const double span = g.best - g.worst;
  if (span == 0.0) return y == g.best ? 1.0 : 0.0;
  return std::clamp((y - g.worst) / span, 0.0, 1.0);
}

Optimum desirability_optimum_3(const std::vector<Goal>& goals) {
  constexpr int kSteps = 40;
  Optimum best;
  best.desirability = -1.0;
  for (int i = 0; i <= kSteps; ++i) {
    for (int j = 0; j <= kSteps; ++j) {
      for (int k = 0; k <= kSteps; ++k) {
        const Eigen::Vector3d x(-1.0 + 2.0 * i / kSteps, -1.0 + 2.0 * j / kSteps,
                                -1.0 + 2.0 * k / kSteps);
        double log_sum = 0.0;
        bool zero = false;
        for (const Goal& g : goals) {
          const double d = desirability(g, predict_quadratic_3(*g.surface, x));
          if (d <= 0.0) zero = true;
          log_sum += std::log(std::max(d, 1e-300));
        }
        const double overall =
            zero || goals.empty() ? 0.0 : std::exp(log_sum / static_cast<double>(goals.size()));
        if (overall > best.desirability + 1e-12) {
          best.desirability = overall;
          best.coded = x;
        }
      }
    }
  }
  return best;
}

}  // namespace planter::doe
