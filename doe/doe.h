#pragma once
// Designs of experiments and their regression analysis, as the paper used them through a
// commercial package: Plackett-Burman screening, Box-Behnken with a quadratic response
// surface, the analysis of variance with p-values, R^2, adjusted R^2, adequate precision and
// lack of fit, and the desirability optimum. Coded factor levels are -1, 0, +1. Forms:
// Montgomery, "Design and Analysis of Experiments", ch. 3, 11 (lack of fit: sec. 11.3);
// Derringer and Suich, "Simultaneous optimization of several response variables", J. Quality
// Technology 12(4), 1980 (desirability).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace planter::doe {

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

// Lack of fit against pure error, from rows run at the same coded settings (replicates).
struct LackOfFit {
  bool available = false;  // needs replicates and more distinct settings than terms
  double ss = 0.0, pure_error_ss = 0.0;
  int df = 0, pure_error_df = 0;
  double f_value = 0.0, p_value = 1.0;
};
LackOfFit lack_of_fit(const Eigen::MatrixXd& coded, const Eigen::VectorXd& y, const Anova& a);

// A goal of the desirability optimum: one response's surface, desirability 0 at `worst` and 1
// at `best`, linear between (Derringer-Suich, weight 1). best > worst maximises, best < worst
// minimises.
struct Goal {
  const Anova* surface = nullptr;
  double worst = 0.0, best = 1.0;
};
double desirability(const Goal& g, double y);
struct Optimum {
  Eigen::Vector3d coded = Eigen::Vector3d::Zero();
  double desirability = 0.0;  // the geometric mean of the goals' desirabilities there
};
// The point of the coded cube [-1, 1]^3 with the highest overall desirability (grid search).
Optimum desirability_optimum_3(const std::vector<Goal>& goals);

}  // namespace planter::doe
