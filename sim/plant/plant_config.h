#pragma once
// Parameters of the machine-and-field model. Every richer effect is off by default, so the
// base model is exactly the nominal structures of docs/recording-format.md.
#include <string>
#include <vector>

#include "config/clamp_ceiling.h"
#include "config/stem_strength.h"
#include "firmware/control/stem_reader.h"
#include "sim/seedling/seedling_force_model.h"
#include "sim/soil/opener_draft.h"
#include "sim/soil/root_anchorage.h"

namespace planter::sim {

struct StopEvent {
  double at_m = 0.0;
  double duration_s = 0.0;
  // The operator switches planting off for the stop (disc stopped, clamp open, opener up) and
  // on again before driving off, as at a belt refill.
  bool planting_off = false;
};

struct RouteConfig {
  double distance_m = 30.0;
  double speed_mps = 0.06;
  double accel_mps2 = 0.03;
  double speed_variation_pct = 0.0;  // slow sinusoidal variation of the driver's speed
  double speed_variation_period_s = 20.0;
  std::vector<StopEvent> stops;
  // Commissioning: someone pushes the machine along the route at this time, controller or
  // not (-1 = it moves only when the controller has started planting).
  double push_at_s = -1.0;
};

struct TerrainConfig {
  double roughness_mm = 0.0;  // amplitude of micro-terrain
  double wavelength_m = 0.5;
  // The share of the terrain's height the furrow's depth takes: the depth-limiting wheel rides
  // the surface but bridges part of it. Assumed (no source), plausible 0.1-0.6.
  double depth_share = 0.3;
};

struct SoilConfig {
  double wheel_radius_m = 0.150;             // true soil-wheel radius
  double slip_mean_pct = 0.0;                // travel reduction of the towed soil wheel
  double slip_variation_pct = 0.0;           // slow variation along the row, sinusoidal over:
  double slip_variation_wavelength_m = 3.7;  // assumed (no source), plausible 1-20 m
  soil::OpenerDraftLaw draft;                // draft on the opener (ASABE D497 form, sim/soil/)
  // The soil that holds the planted root (sim/soil/root_anchorage.h): the loose soil that flows
  // back into the furrow behind the opener, then the same soil once the covering wheel has
  // pressed it. Values and sources: sim/plant/model_values.cpp.
  soil::Soil backflow{14.0, 30.0, 0.5};
  soil::Soil firmed{16.0, 30.0, 3.0};
};

// The seedlings' sizes, feed and strength: plain numbers, so that the scenario's key table
// (sim/runner/scenario_keys.h) takes its defaults from here at compile time.
struct SeedlingSpread {
  double length_min_mm = 182.6, length_max_mm = 210.8;
  double diameter_min_mm = 8.3, diameter_max_mm = 11.4;
  double reference_diameter_mm = StemReaderConfig{}.reference_diameter_mm;
  // Along the disc rim; planted spacing = pitch / sigma. The machine's clamp pitch
  // (machines/*.toml [planting_monitor] clamp_pitch_mm): the Plant sets it from the board.
  double feed_pitch_mm = 0.0;
  double feed_miss_pct = 1.0;    // clamps the feed leaves empty
  double feed_double_pct = 0.0;  // clamps the feed fills with two seedlings
  // Strength: lognormal with the mean and SD of the paper's six measured peaks (Sec. 3.5;
  // config/stem_strength.h); a scenario may set others. Below 0 = from the peaks.
  double strength_mean_N = -1.0;
  double strength_sd_N = -1.0;
  // The strength in use: the scenario's, or the measured peaks'.
  [[nodiscard]] double strength_mean() const {
    return strength_mean_N > 0.0 ? strength_mean_N : config::measured_strength().mean_N;
  }
  [[nodiscard]] double strength_sd() const {
    return strength_sd_N >= 0.0 ? strength_sd_N : config::measured_strength().sd_N;
  }
  // Strength ~ (diameter / reference)^k: assumed, no measurement ties strength to diameter.
  double strength_diameter_exponent = 0.0;
  // The length of seedling the strength test's plates loaded (the paper gives none): the nip
  // loads the held length, so the line load, not the force, is compared (model_values.cpp).
  double strength_test_length_mm = config::ClampCeilingRule{}.specimen_length_mm;
  double density_kg_per_m3 = 870.5;  // the paper's Table 2
  // Tilt scatter the release mechanics leave out (crooked seedlings, settling soil, the covering
  // wheel): calibrated to the paper's centre point (seedling_release.h).
  double tilt_noise_deg = 5.0;
};

struct SeedlingConfig : SeedlingSpread {
  // From the DEM (planter-dem reduce) when the scenario names one: the compression a force
  // gives (peak_compression_mm). Not the strength: that comes from the measured peaks.
  SeedlingForceModel force_model;
  std::string force_model_file;  // as the scenario names it (empty: none)
};

struct MechanismConfig {
  // The machine's as designed (its [clamp_ceiling] table derives the ceiling from the same two).
  double contact_area_mm2 = config::ClampCeilingRule{}.contact_area_mm2;
  // The lips hold the seedling over contact area / diameter along its stem, at most the band of
  // flexible protrusions (the paper, Sec. 3.1 and 5: 40 mm wide).
  double protrusion_band_mm = config::ClampCeilingRule{}.band_mm;
  double carry_angle_deg = 150.0;  // pickup to release
  double nip_time_s = 0.3;         // how long a seedling stays in the roller nip
  // The rim's travel over which the lips close on a stem as it comes under the roller, and open
  // as it leaves (the controller's reading takes the same declared value). The stem's share in
  // the nip grows linearly over it (assumed form).
  double nip_entry_mm = StemReaderConfig{}.entry_mm;
  // The release (sim/plant/seedling_release.h). None of these is tuned: the first three are set
  // once, before any sweep, as the paper gives no value for them; the rest are the paper's or
  // assumed. (The one calibrated value of the release is the seedlings' tilt_noise_deg.)
  double release_after_lowest_deg = 10.0;  // set: where the lips open, past the lowest point
  // The disc rides with the furrow opener on one bracket (the paper, Sec. 2.1, Fig. 2), so the
  // root end's lowest point keeps its height above the furrow floor whatever the depth.
  double root_clearance_mm = 5.0;  // assumed: root end's lowest point above the furrow floor
  // The covering wheel, behind the release, fills the furrow and presses the soil.
  double covering_wheel_behind_mm = 250.0;  // assumed
  // The seedling belt hands the seedling to the lips at a speed that differs by this much from
  // the lips', taken up by friction over the nip time.
  double handoff_speed_mismatch_mps = 0.05;  // assumed
  double residual_grip_share = 0.05;         // set: lip pressure left after release, of the clamp's
  double root_protrusion_mm = 70.0;          // assumed: root end beyond the disc rim
  double backflow_fill = 0.5;  // assumed: share of the furrow refilled at the seedling
  double lip_friction = 0.25;  // seedling on silicone rubber, the paper's 0.2-0.3
  // The lips' elastic turn before the grip gives: the rubber under the contact in shear.
  double lip_shear_modulus_MPa = 1.0;  // assumed: silicone rubber (the paper's "2.9 GPa" cannot be)
  double lip_shear_layer_mm = 10.0;    // assumed: from the 3 mm pad to the 20 mm protrusions
};

struct DriveModelConfig {
  double disc_time_constant_s = 0.05;
  double disc_inertia_kgm2 = 0.6;
  double disc_damping_Nms = 3.0;
  double disc_omega_max_radps = 1.5;
  double actuator_time_constant_s = 0.05;
  double clamp_k_N = 14.85;  // F = k (x - x0)^n, x in mm
  double clamp_x0_mm = 2.0;
  double clamp_n = 1.3;
  // Extra lip compression per mm of seedling over reference; the controller's reading takes the
  // same declared value (firmware/control/stem_reader.h).
  double seedling_thickness_gain = StemReaderConfig{}.thickness_gain;
  double force_noise_N = 1.0;
  double depth_travel_max_mm = 165.0;  // mechanical end stop of the opener actuator
};

struct Effects {
  double disc_coulomb_Nm = 0.0;           // friction in the disc drive train
  double disc_stribeck_Nm = 0.0;          // extra friction near standstill (Stribeck) ...
  double disc_stribeck_radps = 0.05;      // ... fading over this speed
  double disc_deadzone_radps = 0.0;       // dead zone of the speed set-point (forward side) ...
  double disc_deadzone_neg_radps = -1.0;  // ... and reverse side (negative: as forward)
  double disc_backlash_rad = 0.0;         // gear play between motor and disc
  double command_delay_s = 0.0;           // transport delay of the disc speed command
  double slip_per_kN = 0.0;               // wheel slip growing with opener draft (% per kN)
  double clamp_relaxation_frac = 0.0;     // viscoelastic relaxation of the disc lips
  double clamp_relaxation_tau_s = 2.0;
  double clamp_relaxation2_frac = 0.0;  // a second, slower branch (a two-term Prony series)
  double clamp_relaxation2_tau_s = 60.0;
  double depth_sag_mm_per_kN = 0.0;  // opener compliance under soil draft
  double vibration_hz = 0.0;         // engine vibration
  double vibration_force_N = 0.0;
  double vibration_tilt_deg = 0.0;
  double force_offset_N = 0.0;  // load-cell offset
  double force_gain_pct = 0.0;  // load-cell span error
  double force_drift_N_per_min = 0.0;
  // A parameter that changes once, at a time (a new seedling batch, a wetter field): from
  // change_at_s on, the clamp's stiffness and the soil's draft are scaled by these shares.
  double change_at_s = 0.0;
  double clamp_stiffness_change_pct = 0.0;
  double soil_draft_change_pct = 0.0;
  [[nodiscard]] double changed(double pct, double t_s) const {
    return t_s >= change_at_s ? 1.0 + 0.01 * pct : 1.0;
  }
};

struct FaultEvents {
  double estop_at_s = -1.0;
  double estop_release_at_s = -1.0;
  std::string silent_node;  // a node role that stops answering
  double silent_at_s = -1.0;
};

// The GNSS receiver on the machine, as receivers report themselves (sim/plant/gnss_receiver.h).
// Figures of a consumer receiver's datasheet (u-blox NEO-M8, UBX-15031086: velocity accuracy
// 0.05 m/s, navigation rate up to 10 Hz); the rest assumed, with their plausible ranges.
struct GnssConfig {
  double rate_hz = 10.0;          // fixes a second (receivers: 1-10 Hz, some to 25)
  double speed_noise_mps = 0.05;  // on each horizontal axis, 1 sigma, white (the datasheet's)
  double latency_s = 0.05;        // measurement to controller (assumed: 0.02-0.1 s)
  int satellites = 12;            // open sky (assumed, 8-20)
  double hdop = 0.9;              // open sky (assumed, 0.6-1.5)
  // The fix is lost here along the row for this long (a tree line, a building): -1 never.
  double dropout_at_m = -1.0;
  double dropout_s = 5.0;
  // Where the row starts and which way it runs (any field: the figures do not depend on it).
  double origin_lat_deg = 36.7;
  double origin_lon_deg = 117.5;
  double heading_deg = 90.0;
  double position_noise_m = 1.5;  // standalone fix, 1 sigma per axis (assumed, 0.5-3 m)
};

struct PlantConfig {
  GnssConfig gnss;
  RouteConfig route;
  TerrainConfig terrain;
  SoilConfig soil;
  SeedlingConfig seedlings;
  MechanismConfig mechanism;
  DriveModelConfig drive;
  Effects effects;
  double disc_radius_m = 0.300;
  double start_delay_s = 3.0;  // machine starts moving this long after the controller is running
};

}  // namespace planter::sim
