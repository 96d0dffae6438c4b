#pragma once
// The keys of a scenario's [effects] table, declared once: the scenario loader reads them, the
// report lists the ones that ran, and `planter-sim effects` prints them for a user. Each is an
// effect hidden in the plant that the nominal structures (docs/recording-format.md) leave out.
#include <array>

#include "sim/plant/plant_config.h"

namespace planter::sim {

struct EffectKey {
  const char* key;
  double Effects::*member;
  double fallback;  // the value when the key is absent (the effect is off)
  double min, max;
  const char* unit;
  const char* what;
};

inline constexpr std::array<EffectKey, 22> kEffectKeys{{
    {"disc_coulomb_Nm", &Effects::disc_coulomb_Nm, 0.0, 0.0, 100.0, "N*m",
     "Coulomb friction in the disc drive train"},
    {"disc_stribeck_Nm", &Effects::disc_stribeck_Nm, 0.0, 0.0, 100.0, "N*m",
     "extra friction near standstill (Stribeck)"},
    {"disc_stribeck_radps", &Effects::disc_stribeck_radps, 0.05, 0.001, 10.0, "rad/s",
     "the speed over which the Stribeck friction fades"},
    {"disc_deadzone_radps", &Effects::disc_deadzone_radps, 0.0, 0.0, 1.0, "rad/s",
     "dead zone of the disc speed set-point (forward side)"},
    {"disc_deadzone_neg_radps", &Effects::disc_deadzone_neg_radps, -1.0, 0.0, 1.0, "rad/s",
     "dead zone on the reverse side (absent: as forward)"},
    {"disc_backlash_rad", &Effects::disc_backlash_rad, 0.0, 0.0, 0.5, "rad",
     "gear play between motor and disc"},
    {"command_delay_s", &Effects::command_delay_s, 0.0, 0.0, 1.0, "s",
     "transport delay of the disc speed command"},
    {"slip_per_kN", &Effects::slip_per_kN, 0.0, 0.0, 50.0, "%/kN",
     "soil-wheel slip growing with the opener's draft"},
    {"clamp_relaxation_frac", &Effects::clamp_relaxation_frac, 0.0, 0.0, 0.9, "",
     "viscoelastic relaxation of the disc lips: the share that relaxes"},
    {"clamp_relaxation_tau_s", &Effects::clamp_relaxation_tau_s, 2.0, 0.01, 1000.0, "s",
     "its time constant"},
    {"clamp_relaxation2_frac", &Effects::clamp_relaxation2_frac, 0.0, 0.0, 0.9, "",
     "a second, slower relaxation branch (a Prony series of two terms)"},
    {"clamp_relaxation2_tau_s", &Effects::clamp_relaxation2_tau_s, 60.0, 0.01, 10000.0, "s",
     "its time constant"},
    {"depth_sag_mm_per_kN", &Effects::depth_sag_mm_per_kN, 0.0, 0.0, 100.0, "mm/kN",
     "opener compliance under the soil's draft"},
    {"vibration_hz", &Effects::vibration_hz, 0.0, 0.0, 200.0, "Hz", "engine vibration"},
    {"vibration_force_N", &Effects::vibration_force_N, 0.0, 0.0, 100.0, "N",
     "its amplitude on the clamp force"},
    {"vibration_tilt_deg", &Effects::vibration_tilt_deg, 0.0, 0.0, 30.0, "deg",
     "its spread of the seedlings' tilt"},
    {"force_offset_N", &Effects::force_offset_N, 0.0, -100.0, 100.0, "N", "load-cell offset"},
    {"force_gain_pct", &Effects::force_gain_pct, 0.0, -50.0, 50.0, "%", "load-cell span error"},
    {"force_drift_N_per_min", &Effects::force_drift_N_per_min, 0.0, -10.0, 10.0, "N/min",
     "load-cell drift"},
    {"change_at_s", &Effects::change_at_s, 0.0, 0.0, 1e6, "s",
     "when the two changes below take effect"},
    {"clamp_stiffness_change_pct", &Effects::clamp_stiffness_change_pct, 0.0, -90.0, 500.0, "%",
     "the clamp's stiffness changes by this much (a new seedling batch)"},
    {"soil_draft_change_pct", &Effects::soil_draft_change_pct, 0.0, -90.0, 500.0, "%",
     "the soil's draft changes by this much (a wetter field)"},
}};

}  // namespace planter::sim
