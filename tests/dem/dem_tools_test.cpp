// The DEM tools: designs of experiments and their ANOVA, the first-peak rule, the seedling
// builder, parameter files, the reduced-order model, and a calibration that resumes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "config/config_error.h"
#include "dem/calibration.h"
#include "dem/dem_params.h"
#include "dem/seedling.h"
#include "doe/doe.h"
#include "sim/seedling/seedling_force_model.h"

using namespace planter;
using namespace planter::dem;
using namespace planter::doe;

TEST(Doe, PlackettBurmanColumnsAreBalancedAndOrthogonal) {
  const Eigen::MatrixXd d = plackett_burman_12(8);
  ASSERT_EQ(d.rows(), 12);
  const Eigen::MatrixXd xtx = d.transpose() * d;
  EXPECT_TRUE(xtx.isApprox(12.0 * Eigen::MatrixXd::Identity(8, 8)));
  for (int c = 0; c < 8; ++c) EXPECT_DOUBLE_EQ(d.col(c).sum(), 0.0);
}

TEST(Doe, BoxBehnkenHasTheEdgeMidpointsAndACentre) {
  const Eigen::MatrixXd d = box_behnken_3(1);
  ASSERT_EQ(d.rows(), 13);
  for (int r = 0; r < 12; ++r) EXPECT_EQ(d.row(r).cwiseAbs().sum(), 2.0);
  EXPECT_EQ(d.row(12).cwiseAbs().sum(), 0.0);
}

TEST(Doe, MainEffectsRegressionFindsTheActiveFactors) {
  const Eigen::MatrixXd d = plackett_burman_12(8);
  Eigen::VectorXd y(12);
  // y = 100 + 30 x1 - 12 x3 plus a small deterministic "noise".
  for (int r = 0; r < 12; ++r) y(r) = 100.0 + 30.0 * d(r, 0) - 12.0 * d(r, 2) + 0.5 * std::sin(r);
  const Anova a = fit_main_effects(d, y, {"X1", "X2", "X3", "X4", "X5", "X6", "X7", "X8"});
  EXPECT_NEAR(a.terms[0].coefficient, 30.0, 0.5);
  EXPECT_NEAR(a.terms[2].coefficient, -12.0, 0.5);
  EXPECT_LT(a.terms[0].p_value, 0.01);
  EXPECT_LT(a.terms[2].p_value, 0.01);
  EXPECT_LT(std::abs(a.terms[1].coefficient), 0.5);  // inactive: only the small noise
  EXPECT_GT(a.r2, 0.99);
  EXPECT_EQ(a.residual_df, 3);
}

TEST(Doe, QuadraticSurfaceIsRecoveredAndSolvedForATarget) {
  const Eigen::MatrixXd d = box_behnken_3(1);
  Eigen::VectorXd y(13);
  auto truth = [](double a, double b, double c) {
    return 140.0 + 40.0 * a + 10.0 * b - 5.0 * c + 6.0 * a * b + 8.0 * a * a - 3.0 * c * c;
  };
  for (int r = 0; r < 13; ++r) y(r) = truth(d(r, 0), d(r, 1), d(r, 2)) + 0.01 * std::cos(3.0 * r);
  const Anova a = fit_quadratic_3(d, y, {"A", "B", "C"});
  EXPECT_NEAR(a.beta(1), 40.0, 0.05);
  EXPECT_NEAR(a.beta(4), 6.0, 0.05);
  EXPECT_NEAR(a.beta(7), 8.0, 0.1);
  EXPECT_LT(a.model_p, 1e-4);
  EXPECT_GT(a.r2_adjusted, 0.999);
  EXPECT_GT(a.adequate_precision, 4.0);  // the usual "adequate" threshold
  const Eigen::Vector3d x = solve_quadratic_3_for(a, 160.0);
  EXPECT_NEAR(predict_quadratic_3(a, x), 160.0, 1.0);
}

// Lack of fit against the replicates' pure error: a bump at one setting, which no quadratic
// through the other twelve can follow, is found; a quadratic truth with the same replicate noise
// is not flagged.
TEST(Doe, LackOfFitSeparatesAMissingTermFromReplicateNoise) {
  const Eigen::MatrixXd one = box_behnken_3(3);
  Eigen::MatrixXd d(3 * one.rows(), 3);
  d << one, one, one;  // three replicates
  auto fit_and_test = [&](bool bumped) {
    Eigen::VectorXd y(d.rows());
    for (Eigen::Index r = 0; r < d.rows(); ++r) {
      const double a = d(r, 0), b = d(r, 1);
      const bool bump = bumped && a == 1.0 && b == 1.0;
      y(r) = 90.0 + 2.0 * a - 3.0 * b * b + (bump ? 4.0 : 0.0) +
             0.3 * std::sin(7.0 * static_cast<double>(r));  // replicate noise
    }
    const Anova a = fit_quadratic_3(d, y, {"A", "B", "C"});
    return lack_of_fit(d, y, a);
  };
  const LackOfFit missing = fit_and_test(true), none = fit_and_test(false);
  ASSERT_TRUE(missing.available);
  EXPECT_EQ(missing.pure_error_df, 45 - 13);  // 45 runs on 13 distinct settings
  EXPECT_EQ(missing.df, 13 - 10);
  EXPECT_LT(missing.p_value, 1e-6);
  EXPECT_GT(none.p_value, 0.05);
  // Without replicates there is no pure error to test against.
  const Eigen::MatrixXd single = box_behnken_3(1);
  Eigen::VectorXd y(single.rows());
  for (Eigen::Index r = 0; r < single.rows(); ++r) y(r) = single(r, 0);
  EXPECT_FALSE(lack_of_fit(single, y, fit_quadratic_3(single, y, {"A", "B", "C"})).available);
}

// The desirability optimum of two goals: one response up to its maximum, 10 at A = 0.5, one
// down (falling with B): both are met at A = 0.5, B = -1.
TEST(Doe, DesirabilityOptimumMeetsBothGoals) {
  const Eigen::MatrixXd d = box_behnken_3(3);
  Eigen::VectorXd up(d.rows()), down(d.rows());
  for (Eigen::Index r = 0; r < d.rows(); ++r) {
    up(r) = 10.0 - (d(r, 0) - 0.5) * (d(r, 0) - 0.5);
    down(r) = 5.0 + d(r, 1);
  }
  const Anova a_up = fit_quadratic_3(d, up, {"A", "B", "C"});
  const Anova a_down = fit_quadratic_3(d, down, {"A", "B", "C"});
  const Optimum o = desirability_optimum_3(
      {{&a_up, up.minCoeff(), 10.0}, {&a_down, down.maxCoeff(), down.minCoeff()}});
  EXPECT_NEAR(o.coded(0), 0.5, 0.026);
  EXPECT_NEAR(o.coded(1), -1.0, 1e-9);
  EXPECT_GT(o.desirability, 0.99);
  EXPECT_DOUBLE_EQ(desirability({&a_up, 0.0, 10.0}, 12.0), 1.0);  // capped
  EXPECT_DOUBLE_EQ(desirability({&a_down, 6.0, 4.0}, 5.0), 0.5);  // minimised
}

TEST(CompressionTest, FirstPeakIsTheFirstMaximumTheForceFallsFrom) {
  CompressionResult r;
  for (int k = 0; k <= 600; ++k) {
    const double d_mm = 0.01 * k;
    double f = d_mm < 4.0 ? 35.0 * d_mm : 140.0 - 60.0 * (d_mm - 4.0);
    if (d_mm > 5.0) f = 80.0 + 200.0 * (d_mm - 5.0);  // densification: rises above the peak
    r.curve.push_back({d_mm * 1e-3, f + 0.3 * std::sin(7.0 * k), 0});
  }
  find_first_peak(r, 0.05);
  EXPECT_TRUE(r.first_peak_found);
  EXPECT_NEAR(r.peak_force_N, 140.0, 2.0);
  EXPECT_NEAR(r.peak_displacement_m * 1e3, 4.0, 0.1);

  CompressionResult rising;
  for (int k = 0; k <= 100; ++k) rising.curve.push_back({1e-4 * k, 10.0 * k, 0});
  find_first_peak(rising, 0.05);
  EXPECT_FALSE(rising.first_peak_found);
  EXPECT_DOUBLE_EQ(rising.peak_force_N, 1000.0);
}

// What issue 29 found: a first 5 % drop of a few bonds at 2 mm was reported as the peak beside
// a chart whose collapse stood near 185 N. The collapse is found and reported beside it.
TEST(CompressionTest, TheCollapseIsReportedBesideAnEarlierSmallDrop) {
  CompressionResult r;
  for (int k = 0; k <= 600; ++k) {
    const double d_mm = 0.01 * k;
    double f = 66.0 * d_mm;                              // to 138.6 N at 2.1 mm
    if (d_mm > 2.1) f = 138.6 - 90.0 * (d_mm - 2.1);     // a 9 % drop to 2.25 mm
    if (d_mm > 2.25) f = 125.1 + 50.0 * (d_mm - 2.25);   // climbs to 185 N at 3.45 mm
    if (d_mm > 3.45) f = 185.1 - 100.0 * (d_mm - 3.45);  // the collapse, to 100 N at 4.3 mm
    if (d_mm > 4.3) f = 100.0 + 400.0 * (d_mm - 4.3);    // densification, far above both
    r.curve.push_back({d_mm * 1e-3, f, 0});
  }
  find_first_peak(r, 0.05);
  EXPECT_TRUE(r.first_peak_found);
  EXPECT_NEAR(r.peak_force_N, 138.6, 2.0);
  EXPECT_NEAR(r.peak_displacement_m * 1e3, 2.1, 0.1);
  EXPECT_NEAR(r.collapse_force_N, 185.0, 2.0);
  EXPECT_NEAR(r.collapse_displacement_m * 1e3, 3.45, 0.1);
  EXPECT_NEAR(r.collapse_drop_N, 80.0, 6.0);  // 85 N, less the smoothing of the V's bottom
}

TEST(Seedling, HollowDoubleLayerCylinderOfThePaperSize) {
  DemWorld w{ContactMaterial{}, BondParameters{}};
  const SeedlingBuild b = build_seedling(w, SeedlingGeometry{});
  EXPECT_EQ(b.particles, static_cast<int>(w.particles().size()));
  EXPECT_GT(b.particles, 500);
  EXPECT_GT(b.bonds, 3 * b.particles);  // every particle bonded to its ring and neighbours
  double z_min = 1, z_max = -1, r_min = 1, r_max = 0;
  for (const auto& p : w.particles()) {
    EXPECT_DOUBLE_EQ(p.radius_m, 1.5e-3);
    const double r = std::hypot(p.x.x(), p.x.y());
    r_min = std::min(r_min, r);
    r_max = std::max(r_max, r);
    z_min = std::min(z_min, p.x.z() - p.radius_m);
    z_max = std::max(z_max, p.x.z() + p.radius_m);
  }
  EXPECT_NEAR(r_max + 1.5e-3, 5e-3, 1e-9);  // 10 mm outside diameter
  EXPECT_GT(r_min, 1e-4);                   // hollow: no particle on the axis
  EXPECT_NEAR(z_max - z_min, 0.190, 3e-3);  // 190 mm, to a particle diameter
}

TEST(DemParams, ABadKeyOrValueNamesTheFileLineAndKey) {
  const std::string path = testing::TempDir() + "/bad_params.toml";
  {
    std::ofstream f(path);
    f << "[bond]\nnormal_stiffness_N_m3 = 4.8e9\ntensile_strengh_Pa = 5e7\n";
  }
  try {
    load_compression_setup(path);
    FAIL() << "a misspelt key was accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(std::string(e.what()).find("tensile_strengh_Pa"), std::string::npos);
  }
  {
    std::ofstream f(path);
    f << "[test]\nspeedup = 0.5\n";
  }
  EXPECT_THROW(load_compression_setup(path), config::ConfigError);
  // What compress writes beside its results is a valid parameter file with the same values.
  CompressionSetup s;
  s.bonds.tensile_strength_Pa = 2.5e4;
  s.seedling.diameter_m = 9.3e-3;
  {
    std::ofstream f(path);
    f << compression_setup_toml(s);
  }
  const CompressionSetup back = load_compression_setup(path);
  EXPECT_DOUBLE_EQ(back.bonds.tensile_strength_Pa, 2.5e4);
  EXPECT_NEAR(back.seedling.diameter_m, 9.3e-3, 1e-12);
}

TEST(SeedlingForceModel, CompressionInvertsTheElasticBranch) {
  sim::SeedlingForceModel m;
  m.exponent = 1.3;
  m.stiffness_N_per_mm_n = 25.0;
  m.stiffness_slope_per_mm = 4.0;
  for (double d : {8.3, 10.0, 11.4}) {
    for (double f : {10.0, 90.0, 140.0}) {
      EXPECT_NEAR(m.force_N(d, m.compression_mm(d, f), 0.0), f, 1e-9);
    }
  }
}

TEST(Calibration, AnInterruptedCalibrationResumesWithoutRerunning) {
  CalibrationOptions o;
  // A short seedling, a short fast stroke: this tests the workflow, not the physics, and
  // must stay quick under the sanitizers too (150 steps of 22 particles a run).
  o.base.seedling.length_m = 0.006;
  o.base.stroke_m = 0.5e-3;
  o.base.speedup = 500.0;
  o.base.samples = 30;
  o.jobs = 2;
  o.target_N = 20.0;
  o.refinement_runs = 0;  // the paper's workflow only: a fixed number of runs
  o.out_dir = testing::TempDir() + "/calibration_resume";
  std::filesystem::remove_all(o.out_dir);
  auto quiet = [](const std::string&) {};
  o.max_new_runs = 5;
  const CalibrationReport first = calibrate(o, quiet);
  EXPECT_FALSE(first.complete);
  EXPECT_EQ(first.new_runs, 5);
  o.max_new_runs = -1;
  const CalibrationReport second = calibrate(o, quiet);
  EXPECT_TRUE(second.complete);
  // The 5 done before, and any design point that repeats an earlier one (the Box-Behnken
  // centre is the best ascent step): never simulated twice.
  EXPECT_GE(second.reused_runs, 5);
  EXPECT_EQ(second.new_runs + second.reused_runs, 12 + 8 + 13 + 1);
  EXPECT_EQ(first.new_runs + second.new_runs + (second.reused_runs - 5) - first.reused_runs,
            12 + 8 + 13 + 1);
  write_calibration_outputs(o, second);
  EXPECT_TRUE(std::filesystem::exists(o.out_dir + "/calibrated.toml"));
  // The calibrated file is a parameter file planter-dem accepts.
  EXPECT_NO_THROW(load_compression_setup(o.out_dir + "/calibrated.toml"));
  // Same runs, same answer, whatever the number of jobs.
  CalibrationOptions one = o;
  one.jobs = 1;
  one.out_dir = o.out_dir + "_one_job";
  std::filesystem::remove_all(one.out_dir);
  const CalibrationReport serial = calibrate(one, quiet);
  EXPECT_EQ(serial.verification.result.peak_force_N, second.verification.result.peak_force_N);
}
