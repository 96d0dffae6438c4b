#pragma once
// Designs of experiments and their regression analysis, as the paper used them through a
// commercial package: Plackett-Burman screening, Box-Behnken with a quadratic response
// surface, and the analysis of variance with p-values, R^2, adjusted R^2 and adequate
// precision. Coded factor levels are -1, 0, +1.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace planter::dem {

// 12 runs for up to 11 two-level factors (Plackett and Burman's generator, cyclic).
Eigen::MatrixXd plackett_burman_12(int factors);
// Box-Behnken for 3 factors: the 12 edge midpoints and `centre_points` centres.
Eigen::MatrixXd box_behnken_3(int centre_points);

struct TermTest {
  std::string name;
  double coefficient = 0.0;
  double sum_of_squares = 0.0;  // partial (type III) for this term
  double f_value = 0.0;
  double p_value = 1.0;
};

struct Anova {
  std::vector<TermTest> terms;  // without the intercept
  double intercept = 0.0;
  double model_ss = 0.0, residual_ss = 0.0;
  int model_df = 0, residual_df = 0;
  double model_f = 0.0, model_p = 1.0;
  double r2 = 0.0, r2_adjusted = 0.0;
  double adequate_precision = 0.0;  // range of predictions over their mean standard error
  Eigen::VectorXd beta;             // intercept first, then the terms
};

// Main effects only (screening): y = b0 + sum b_i x_i.
Anova fit_main_effects(const Eigen::MatrixXd& coded, const Eigen::VectorXd& y,
                       const std::vector<std::string>& names);
// Full quadratic in 3 factors: b0, A, B, C, AB, AC, BC, A^2, B^2, C^2.
Anova fit_quadratic_3(const Eigen::MatrixXd& coded, const Eigen::VectorXd& y,
                      const std::vector<std::string>& names);
double predict_quadratic_3(const Anova& a, const Eigen::Vector3d& x);
// The point of the coded cube [-1, 1]^3 whose prediction is nearest `target` (grid search;
// of equal ones, the nearest the centre).
Eigen::Vector3d solve_quadratic_3_for(const Anova& a, double target);

}  // namespace planter::dem
