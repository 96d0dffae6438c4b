// The disc drive train's optional effects in the plant: what planter-fit's blind proof hides.
#include "sim/plant/drive_models.h"

#include <gtest/gtest.h>

using namespace planter::sim;

namespace {
constexpr double kDt_s = 0.001;

double omega_after(DiscDriveModel& drive, double omega_target, double seconds) {
  for (double t = 0; t < seconds; t += kDt_s) drive.step(omega_target, true, false, kDt_s);
  return drive.omega();
}
}  // namespace

// The textbook dead zone: nothing inside the band, the set-point less the band beyond it.
TEST(DiscDriveModel, DeadZoneTakesItsWidthOffLargerSetPoints) {
  Effects fx;
  fx.disc_deadzone_radps = 0.1;
  DiscDriveModel drive(DriveModelConfig{}, fx);
  EXPECT_EQ(omega_after(drive, 0.08, 1.0), 0.0);
  EXPECT_NEAR(omega_after(drive, 0.3, 1.0), 0.2, 0.01);
  EXPECT_NEAR(omega_after(drive, -0.3, 1.0), -0.2, 0.01);
  fx.disc_deadzone_neg_radps = 0.05;  // asymmetric
  DiscDriveModel asymmetric(DriveModelConfig{}, fx);
  EXPECT_NEAR(omega_after(asymmetric, -0.3, 1.0), -0.25, 0.01);
  EXPECT_NEAR(omega_after(asymmetric, 0.3, 1.0), 0.2, 0.01);
}

// Stribeck friction holds the disc at rest against a torque the Coulomb level alone would
// not, and costs only the Coulomb level once the disc runs well above the Stribeck speed.
TEST(DiscDriveModel, StribeckFrictionFadesWithSpeed) {
  DriveModelConfig d;
  Effects coulomb, stribeck;
  coulomb.disc_coulomb_Nm = 1.0;
  stribeck.disc_coulomb_Nm = 1.0;
  stribeck.disc_stribeck_Nm = 3.0;
  stribeck.disc_stribeck_radps = 0.05;
  DiscDriveModel a(d, coulomb), b(d, stribeck);
  omega_after(a, 0.3, 2.0);
  omega_after(b, 0.3, 2.0);
  EXPECT_NEAR(a.torque_Nm(), b.torque_Nm(), 0.01 * a.torque_Nm());
  // From rest, a set-point whose loop torque stays below 1 + 3 N m never breaks away.
  DiscDriveModel c(d, stribeck);
  const double small_radps =
      3.0 / (d.disc_inertia_kgm2 / d.disc_time_constant_s + d.disc_damping_Nms);
  EXPECT_EQ(omega_after(c, small_radps, 1.0), 0.0);
  DiscDriveModel e(d, coulomb);
  EXPECT_GT(omega_after(e, small_radps, 1.0), 0.0);
}
