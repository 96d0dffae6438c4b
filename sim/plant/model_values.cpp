#include "sim/plant/model_values.h"

#include <array>
#include <cstdio>

namespace planter::sim {
namespace {

using O = ValueOrigin;
// The strength's mean and SD default to the measured peaks' (unset in the config): the table
// shows and varies the value in use, so it is written into the config first.
double& strength_mean(PlantConfig& c) {
  c.seedlings.strength_mean_N = c.seedlings.strength_mean();
  return c.seedlings.strength_mean_N;
}
double& strength_sd(PlantConfig& c) {
  c.seedlings.strength_sd_N = c.seedlings.strength_sd();
  return c.seedlings.strength_sd_N;
}

// Ranges: a measured value's is its uncertainty (the mean's 95 % interval from six specimens,
// the SD's chi-square interval on 5 df); an assumed value's is what a reader of the soil or
// rubber literature would accept for this machine and field; nothing here was chosen to land on
// a figure of the paper.
const std::array kValues{
    ModelValue{"seedlings.density_kg_per_m3", "kg/m^3", O::measured, 826.5, 914.5,
               "the paper, Sec. 3.3: 870.5 +- 22.0 (range: +-2 SD)",
               [](PlantConfig& c) -> double& { return c.seedlings.density_kg_per_m3; }},
    ModelValue{"seedlings.strength_mean_N", "N", O::measured, 134.6, 189.2,
               "the paper, Sec. 3.5: mean of the six measured peaks (range: its 95 % interval)",
               strength_mean},
    ModelValue{"seedlings.strength_sd_N", "N", O::measured, 15.7, 61.6,
               "the paper, Sec. 3.5: SD of the six peaks (range: chi-square 95 %, 5 df); "
               "lognormal form assumed",
               strength_sd},
    ModelValue{"seedlings.strength_diameter_exponent", "", O::assumed, 0.0, 2.0,
               "assumed: no measurement ties strength to diameter (the DEM's slope is its "
               "particle scaling, not data)",
               [](PlantConfig& c) -> double& { return c.seedlings.strength_diameter_exponent; }},
    ModelValue{"seedlings.strength_test_length_mm", "mm", O::assumed, 15.0, 50.0,
               "assumed: the paper does not give the compressed specimen's length",
               [](PlantConfig& c) -> double& { return c.seedlings.strength_test_length_mm; }},
    ModelValue{"seedlings.tilt_noise_deg", "deg", O::calibrated, 2.0, 8.0,
               "calibrated once to the paper's centre point (1 value); the centre point's "
               "uprightness is therefore no validation",
               [](PlantConfig& c) -> double& { return c.seedlings.tilt_noise_deg; }},
    ModelValue{"mechanism.lip_friction", "", O::measured, 0.2, 0.3,
               "the paper, Sec. 3.4: seedling on silicone rubber, static friction 0.2-0.3",
               [](PlantConfig& c) -> double& { return c.mechanism.lip_friction; }},
    ModelValue{"mechanism.lip_shear_modulus_MPa", "MPa", O::assumed, 0.3, 2.9,
               "assumed: silicone rubber, Shore 30-70A; the paper's Sec. 3.3 gives 2.9 GPa, a "
               "thousand times a rubber's, read here as 2.9 MPa (the range's top)",
               [](PlantConfig& c) -> double& { return c.mechanism.lip_shear_modulus_MPa; }},
    ModelValue{"mechanism.lip_shear_layer_mm", "mm", O::assumed, 3.0, 20.0,
               "assumed: the rubber sheared under the contact, from the 3 mm pad (the paper, "
               "Sec. 3.3) to the 20 mm protrusions (Sec. 3.1)",
               [](PlantConfig& c) -> double& { return c.mechanism.lip_shear_layer_mm; }},
    ModelValue{"mechanism.protrusion_band_mm", "mm", O::design, 20.0, 40.0,
               "the paper, Sec. 3.1 and 5: protrusions over a 40 mm band (20 mm the other "
               "arrangement tried)",
               [](PlantConfig& c) -> double& { return c.mechanism.protrusion_band_mm; }},
    ModelValue{"mechanism.root_protrusion_mm", "mm", O::assumed, 40.0, 100.0,
               "assumed: how far the root end reaches beyond the rim (the belt's placement)",
               [](PlantConfig& c) -> double& { return c.mechanism.root_protrusion_mm; }},
    ModelValue{"mechanism.root_clearance_mm", "mm", O::assumed, 0.0, 20.0,
               "assumed: the root end's lowest point above the furrow floor; the disc rides "
               "with the opener (the paper, Sec. 2.1, Fig. 2)",
               [](PlantConfig& c) -> double& { return c.mechanism.root_clearance_mm; }},
    ModelValue{"mechanism.release_after_lowest_deg", "deg", O::assumed, 0.0, 20.0,
               "assumed: where the roller leaves the lips, past the lowest point",
               [](PlantConfig& c) -> double& { return c.mechanism.release_after_lowest_deg; }},
    ModelValue{"mechanism.residual_grip_share", "", O::assumed, 0.0, 0.15,
               "assumed: lip pressure left after the release, of the clamp's",
               [](PlantConfig& c) -> double& { return c.mechanism.residual_grip_share; }},
    ModelValue{"mechanism.backflow_fill", "", O::assumed, 0.3, 0.7,
               "assumed: share of the furrow the returning soil refills at the seedling",
               [](PlantConfig& c) -> double& { return c.mechanism.backflow_fill; }},
    ModelValue{"mechanism.covering_wheel_behind_mm", "mm", O::assumed, 150.0, 400.0,
               "assumed: the covering wheel's distance behind the release (the paper's Fig. 5b "
               "shows it, without a dimension)",
               [](PlantConfig& c) -> double& { return c.mechanism.covering_wheel_behind_mm; }},
    ModelValue{"mechanism.handoff_speed_mismatch_mps", "m/s", O::assumed, 0.0, 0.15,
               "assumed: belt against lips at the hand-off",
               [](PlantConfig& c) -> double& { return c.mechanism.handoff_speed_mismatch_mps; }},
    ModelValue{"mechanism.nip_time_s", "s", O::assumed, 0.15, 0.5,
               "assumed: how long a seedling stays in the roller's nip",
               [](PlantConfig& c) -> double& { return c.mechanism.nip_time_s; }},
    ModelValue{"mechanism.nip_entry_mm", "mm", O::assumed, 5.0, 20.0,
               "assumed: the rim's travel over which the lips close on a stem (the paper's 20 mm "
               "roller's radius, 10 mm; its diameter at most)",
               [](PlantConfig& c) -> double& { return c.mechanism.nip_entry_mm; }},
    ModelValue{"soil.unit_weight_kN_per_m3", "kN/m^3", O::assumed, 12.0, 16.0,
               "assumed: the returned, loose loam",
               [](PlantConfig& c) -> double& { return c.soil.backflow.unit_weight_kN_per_m3; }},
    ModelValue{"soil.friction_angle_deg", "deg", O::assumed, 25.0, 35.0,
               "assumed: loam's friction angle, loose and firmed alike",
               [](PlantConfig& c) -> double& { return c.soil.backflow.friction_angle_deg; }},
    ModelValue{"soil.cohesion_kPa", "kPa", O::assumed, 0.0, 2.0,
               "assumed: apparent cohesion of the loose returned soil (its structure broken)",
               [](PlantConfig& c) -> double& { return c.soil.backflow.cohesion_kPa; }},
    ModelValue{"soil.firmed_unit_weight_kN_per_m3", "kN/m^3", O::assumed, 14.0, 18.0,
               "assumed: the loam after the covering wheel",
               [](PlantConfig& c) -> double& { return c.soil.firmed.unit_weight_kN_per_m3; }},
    ModelValue{"soil.firmed_cohesion_kPa", "kPa", O::assumed, 1.0, 10.0,
               "assumed: apparent cohesion of moist loam pressed by the covering wheel",
               [](PlantConfig& c) -> double& { return c.soil.firmed.cohesion_kPa; }},
    ModelValue{"plant.seedling_thickness_gain", "", O::assumed, 0.25, 1.0,
               "assumed: extra lip compression per mm of seedling over the reference",
               [](PlantConfig& c) -> double& { return c.drive.seedling_thickness_gain; }},
    // The nip's stem (sim/plant/clamp_nip.h), from the DEM's reduced law when the scenario names
    // one. Its bonds were tuned at one particle size and the same bonds give a peak 1.4-3.6 times
    // as high at others (models/seedling_dem.toml): the law is known within about a factor of
    // two in stiffness, its exponent and its drop less so.
    ModelValue{
        "seedlings.stem_stiffness_N_per_mm_n", "N/mm^n", O::calibrated, 12.0, 50.0,
        "calibrated: the DEM's reduced law (planter-dem reduce, 1.5 mm particles); range "
        "assumed, half to twice it (the DEM's resolution moves its peak 1.4-3.6 times)",
        [](PlantConfig& c) -> double& { return c.seedlings.force_model.stiffness_N_per_mm_n; }},
    ModelValue{"seedlings.stem_exponent", "", O::calibrated, 1.2, 1.8,
               "calibrated: the DEM's reduced law; range assumed (a tube between plates, 1.5 "
               "near contact, stiffening or softening as the wall bends)",
               [](PlantConfig& c) -> double& { return c.seedlings.force_model.exponent; }},
    ModelValue{"seedlings.stem_residual_fraction", "", O::calibrated, 0.3, 0.8,
               "calibrated: the DEM's drop after its first peak (93 of 146 N); range assumed",
               [](PlantConfig& c) -> double& { return c.seedlings.force_model.residual_fraction; }},
};

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

}  // namespace

const char* origin_name(ValueOrigin o) {
  switch (o) {
    case ValueOrigin::measured:
      return "measured";
    case ValueOrigin::design:
      return "design";
    case ValueOrigin::assumed:
      return "assumed";
    case ValueOrigin::calibrated:
      return "calibrated";
  }
  return "?";
}

std::span<const ModelValue> model_values() { return kValues; }

std::string model_values_text(const PlantConfig& c) {
  std::string out;
  char line[512];
  for (const ModelValue& v : kValues) {
    std::snprintf(line, sizeof line, "%-40s %9s %-7s %9s-%-9s %-10s %s\n", v.key,
                  number(v.value(c)).c_str(), v.unit, number(v.low).c_str(), number(v.high).c_str(),
                  origin_name(v.origin), v.source);
    out += line;
  }
  return out;
}

std::string model_values_html(const PlantConfig& c) {
  std::string h =
      "<table><tr><th>value</th><th>in use</th><th>unit</th><th>plausible range</th>"
      "<th>origin</th><th>source</th></tr>";
  for (const ModelValue& v : kValues) {
    h += std::string("<tr><td style='text-align:left'>") + v.key + "</td><td>" +
         number(v.value(c)) + "</td><td>" + v.unit + "</td><td>" + number(v.low) + " - " +
         number(v.high) + "</td><td>" + origin_name(v.origin) +
         "</td><td style='text-align:left'>" + v.source + "</td></tr>";
  }
  return h + "</table>";
}

}  // namespace planter::sim
