// A dead zone on the disc's speed beside a Coulomb friction on its torque: reported as the
// friction seen through a proportional speed loop when its width is F T_d / J, not otherwise.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "analysis/mismatch.h"

namespace planter::analysis {
namespace {

const ChannelModel& channel(const std::string& output) {
  for (const ChannelModel* c : all_channels())
    if (c->output() == output) return *c;
  throw std::runtime_error("no channel " + output);
}

// The simulator's disc: J = 0.6 kg m^2, loop stiffness 13 N m s/rad (T_d = 0.6 / 13 s), a
// Coulomb friction of 2 N m: the speed stays 2 / 13 = 0.1538 rad/s below its command.
FitReport disc_report(double dead_zone_width, bool with_friction,
                      EffectKind band = EffectKind::kDeadZone) {
  FitReport rep;
  ChannelReport speed;
  speed.channel = &channel("omega");
  speed.final_fit.nominal = {0.6 / 13.0, 2.0};
  speed.final_fit.nominal_sd = {0.0005, 0.0};
  speed.final_fit.effects.push_back({&effect_spec(band), {dead_zone_width}});
  speed.final_fit.effect_sd = {{0.0012}};
  ChannelReport torque;
  torque.channel = &channel("disc_torque");
  torque.final_fit.nominal = {0.6, 3.0};
  torque.final_fit.nominal_sd = {0.004, 0.01};
  if (with_friction) {
    torque.final_fit.effects.push_back({&effect_spec(EffectKind::kCoulomb), {2.0}});
    torque.final_fit.effect_sd = {{0.01}};
  }
  rep.channels = {speed, torque};
  return rep;
}

TEST(SpeedLoopDeficit, ADeadZoneOfTheFrictionsWidthIsTheFrictionThroughTheLoop) {
  FitReport rep = disc_report(0.1538, true);
  judge_speed_loop_deficit(rep);
  const auto* x = rep.channels[0].explained_by(0);
  ASSERT_NE(x, nullptr);
  EXPECT_EQ(x->relation, ChannelReport::ExplainedBy::Relation::kThroughSpeedLoop);
  EXPECT_EQ(x->by, "disc_torque:Coulomb friction");
  EXPECT_NE(x->note.find("0.1538"), std::string::npos) << x->note;
}

// The speed channel's own form of that friction (the band with its stop) is linked the same way,
// and said to be the same friction rather than "not a dead zone of the drive".
TEST(SpeedLoopDeficit, TheFrictionBandOnTheSpeedIsTheTorquesFriction) {
  FitReport rep = disc_report(0.1538, true, EffectKind::kLoopFriction);
  judge_speed_loop_deficit(rep);
  const auto* x = rep.channels[0].explained_by(0);
  ASSERT_NE(x, nullptr);
  EXPECT_EQ(x->by, "disc_torque:Coulomb friction");
  EXPECT_NE(x->note.find("the same friction"), std::string::npos) << x->note;
  EXPECT_EQ(x->note.find("not a dead zone"), std::string::npos) << x->note;
}

TEST(SpeedLoopDeficit, AWiderDeadZoneOrNoFrictionStaysADeadZone) {
  FitReport wider = disc_report(0.2, true);  // 30 % over F T_d / J, far beyond its SDs
  judge_speed_loop_deficit(wider);
  EXPECT_TRUE(wider.channels[0].explained.empty());
  FitReport alone = disc_report(0.1538, false);
  judge_speed_loop_deficit(alone);
  EXPECT_TRUE(alone.channels[0].explained.empty());
}

}  // namespace
}  // namespace planter::analysis
