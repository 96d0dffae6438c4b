#pragma once
// Soil draft on the furrow opener, in the form of ASAE/ASABE D497 (Agricultural Machinery
// Management Data), whose table rows come from Harrigan & Rotz, "Draft relationships for
// tillage and seeding equipment", Appl. Eng. Agric. 11(6), 1995:
//   D = F_i (A + B S + C S^2) W T,  S in km/h, W tools, T depth in cm.
// This machine has one opener (W = 1). The depth enters as T_ref (d / T_ref)^m: m = 1 is the
// standard's linear law; wedge mechanics (McKyes, "Soil Cutting and Tillage", 1985, ch. 4) add
// a depth-squared term from the soil's weight, so m lies between 1 and 2.
// Defaults: the row "chisel plow, 5 cm straight point, per tool" (the narrow tine closest to an
// opener): A = 91 N/cm, B = 5.4 N/(cm km/h), C = 0; texture factor F = 1.0 fine, 0.85 medium,
// 0.65 coarse. The standard states about +-50 % for an unknown soil.
// Not in the standard: starting and stopping. Soil failure in front of a tine is rate-independent
// (McKyes), so the draft of a moving opener does not depend on how slowly it moves; it is built
// up over travel, as soil shear stress is mobilised over shear displacement in the
// Janosi-Hanamoto form 1 - exp(-j/K) (Wong, "Theory of Ground Vehicles", ch. 2), and at rest it
// relaxes away with a time constant. The mobilised share s obeys
//   ds/dx = (1 - s) / K  while moving forward,   ds/dt = -s / tau  always,
// so a steady speed v holds s = 1 / (1 + K / (v tau)), a speed dependence under 1 % at working
// speeds. K and tau are assumed (two parameters, not tuned): K = 10 mm, of the order of the
// shear deformation moduli of loams; tau = 30 s, soil stress relaxation over tens of seconds.
// The share, not the speed, carries the start: a noisy speed at rest would otherwise pass
// through a steep onset as draft.
#include <algorithm>
#include <cmath>
#include <string_view>

namespace planter::soil {

struct OpenerDraftLaw {
  double a_N_per_cm = 91.0;         // A: the speed-independent part, per cm of depth
  double b_N_per_cm_kmh = 5.4;      // B
  double c_N_per_cm_kmh2 = 0.0;     // C
  double texture_factor = 0.85;     // F_i (medium texture)
  double depth_exponent = 1.0;      // m
  double mobilisation_mm = 10.0;    // K: travel over which the draft builds up
  double rest_relaxation_s = 30.0;  // tau: relaxation of the draft at rest
};

inline constexpr double kDraftReferenceDepth_mm = 100.0;  // T_ref

// F_i of D497 for a texture name; negative for an unknown name.
inline double texture_factor_of(std::string_view texture) {
  if (texture == "fine") return 1.0;
  if (texture == "medium") return 0.85;
  if (texture == "coarse") return 0.65;
  return -1.0;
}

// The relaxation over a step of dt_s alone. A fit over evenly sampled rows computes it once
// for all its steps (mobilised_share_after).
inline double rest_decay(const OpenerDraftLaw& law, double dt_s) {
  return std::exp(-std::max(0.0, dt_s) / law.rest_relaxation_s);
}

// mobilised_share with the step's rest_decay given.
inline double mobilised_share_after(const OpenerDraftLaw& law, double share, double travel_m,
                                    double decay) {
  // exp(0) is 1: no exp for a step without travel.
  const double unloaded = travel_m > 0.0 ? std::exp(-travel_m * 1e3 / law.mobilisation_mm) : 1.0;
  const double loaded = 1.0 - (1.0 - share) * unloaded;
  return loaded * decay;
}

// The mobilised share after a step of forward travel and time: exact for a step at constant
// speed taken as travel then relaxation (the plant steps 1 ms, the fit its analysed rate).
// Backward travel does not unload: this machine does not reverse, and a noisy speed at rest
// must not be read as unloading.
inline double mobilised_share(const OpenerDraftLaw& law, double share, double travel_m,
                              double dt_s) {
  return mobilised_share_after(law, share, travel_m, rest_decay(law, dt_s));
}

// The share held at a steady forward speed (the fixed point of the law above, continuous).
inline double steady_mobilised_share(const OpenerDraftLaw& law, double v_mps) {
  if (v_mps <= 0.0) return 0.0;
  return 1.0 / (1.0 + law.mobilisation_mm * 1e-3 / (v_mps * law.rest_relaxation_s));
}

// (A + B S + C S^2) with S in km/h, per cm of depth.
inline double draft_per_cm_N(const OpenerDraftLaw& law, double v_mps) {
  const double s_kmh = 3.6 * std::max(0.0, v_mps);
  return law.a_N_per_cm + law.b_N_per_cm_kmh * s_kmh + law.c_N_per_cm_kmh2 * s_kmh * s_kmh;
}

// T_ref (d / T_ref)^m in cm. D497's own form is linear in depth (m = 1), where pow(x, 1) is x
// (the exact value is representable and glibc's pow is within 0.52 ULP of it): no pow a plant
// step for it.
inline double draft_depth_cm(double depth_mm, double depth_exponent) {
  const double ratio = std::max(0.0, depth_mm) / kDraftReferenceDepth_mm;
  return 0.1 * kDraftReferenceDepth_mm *
         (depth_exponent == 1.0 ? ratio : std::pow(ratio, depth_exponent));
}

// draft_depth_cm from ln(d / T_ref) (-inf at or above the surface): a fit that varies m over
// the same depths takes the logarithm once a row and no pow.
inline double draft_depth_cm_of_log(double log_depth_ratio, double depth_exponent) {
  return 0.1 * kDraftReferenceDepth_mm * std::exp(depth_exponent * log_depth_ratio);
}

// The draft with the mobilised share s (mobilised_share).
inline double opener_draft_N(const OpenerDraftLaw& law, double v_mps, double depth_mm,
                             double share) {
  return law.texture_factor * draft_per_cm_N(law, v_mps) *
         draft_depth_cm(depth_mm, law.depth_exponent) * share;
}

}  // namespace planter::soil
