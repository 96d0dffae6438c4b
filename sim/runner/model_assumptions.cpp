#include "sim/runner/model_assumptions.h"

#include <cstdio>

#include "sim/plant/effect_keys.h"
#include "sim/plant/seedling_process.h"
#include "sim/runner/summary.h"

namespace planter::sim {
namespace {

// printf into a std::string (the report is built once, after the run).
template <typename... Args>
std::string format(const char* fmt, Args... args) {
  const int n = std::snprintf(nullptr, 0, fmt, args...);
  std::string out(static_cast<std::size_t>(n > 0 ? n : 0), '\0');
  std::snprintf(out.data(), out.size() + 1, fmt, args...);
  return out;
}

std::string strength(const SeedlingConfig& c) {
  const double cv_pct = 100.0 * c.strength_sd_N / c.strength_mean_N;
  if (c.force_model.loaded) {
    const SeedlingForceModel& m = c.force_model;
    return format(
        "Seedling strength: the first peak of the DEM's reduced-order model (%s): %.1f N at "
        "%.1f mm of compression for a %.1f mm seedling, %+.1f N per mm of diameter, so it "
        "follows each seedling's diameter (%.1f-%.1f mm); spread with a coefficient of variation "
        "of %.1f %% (strength_sd_N / strength_mean_N = %.1f / %.1f N). A seedling is damaged "
        "when the radial force in the roller nip exceeds its strength.",
        c.force_model_file.c_str(), m.peak_force_N, m.peak_displacement_mm, m.reference_diameter_mm,
        m.peak_force_slope_N_per_mm, c.diameter_min_mm, c.diameter_max_mm, cv_pct, c.strength_sd_N,
        c.strength_mean_N);
  }
  return format(
      "Seedling strength: normal, mean %.1f N, SD %.1f N, the same for every diameter (no DEM "
      "force model named in [seedlings]). A seedling is damaged when the radial force in the "
      "roller nip exceeds its strength.",
      c.strength_mean_N, c.strength_sd_N);
}

std::string effects(const Effects& e) {
  std::string on;
  for (const EffectKey& k : kEffectKeys) {
    const double v = e.*k.member;
    if (v == k.fallback) continue;
    on += format("%s%s = %g %s (%s)", on.empty() ? "" : "; ", k.key, v, k.unit, k.what);
  }
  if (on.empty()) return "Hidden effects: none; the plant is the nominal structure of PRODUCT.md.";
  return "Hidden effects on (the [effects] table): " + on + ".";
}

}  // namespace

std::vector<std::string> model_assumptions(const Scenario& sc) {
  const PlantConfig& p = sc.plant;
  const soil::OpenerDraftLaw& d = p.soil.draft;
  const MechanismConfig& m = p.mechanism;
  const DriveModelConfig& dr = p.drive;
  return {
      strength(p.seedlings),
      format("Radial force on a seedling = clamp force x a contact-area factor "
             "1 + 0.15 ((A - 255 mm^2) / 150 mm^2)^2, a shape after the paper's Fig. 17b (2 "
             "values read from it, not mechanics); here A = %.0f mm^2, a factor of %.3f. Thicker "
             "seedlings compress the lips further.",
             m.contact_area_mm2, contact_area_factor(m.contact_area_mm2)),
      format("Tilt from the release mechanics (sim/plant/seedling_release.h): a rigid seedling "
             "(density %.1f kg/m^3) held radially, root end %.0f mm beyond the rim; the root "
             "plowed through the soil turns it in the clamp when the soil's moment beats the "
             "lips' friction moment (mu %.2f, the paper's); released %.1f deg past the lowest "
             "point, the leaves dragged by the lips with %.3f of the clamp force until the top "
             "leaves the disc, against the root's anchorage (Broms' short pile, soil %.1f kN/m^3, "
             "phi %.0f deg, both assumed); lodged when its weight's moment beats the soil's. "
             "Set once, not tuned, as the paper gives none: the release angle, the residual "
             "grip and the root reach (%.0f mm below the surface at the lowest point, the "
             "paper's optimum depth). Calibrated to the paper's centre point (1 value): the "
             "scatter the stages leave out, %.1f deg. Uprightness = mean of (1 - |tilt| / 90 "
             "deg), the paper's definition.",
             p.seedlings.density_kg_per_m3, m.root_protrusion_mm, m.lip_friction,
             m.release_after_lowest_deg, m.residual_grip_share,
             1e-3 * p.soil.ground.unit_weight_N_per_m3, p.soil.ground.friction_angle_deg,
             m.root_reach_mm, p.seedlings.tilt_noise_deg),
      format("Clamp (the disc lips): F = k (x - x0)^n with k = %.2f, x0 = %.2f mm, n = %.2f "
             "([plant]); load-cell noise %.1f N.",
             dr.clamp_k_N, dr.clamp_x0_mm, dr.clamp_n, dr.force_noise_N),
      format("Soil draft on the opener in ASABE D497's form: F_i (A + B S + C S^2) T_ref "
             "(d / T_ref)^m with F_i = %.2f, A = %.1f N/cm, B = %.2f N/(cm km/h), C = %.2f "
             "N/(cm (km/h)^2), T_ref = %.0f mm, m = %.2f; built up over %.0f mm of travel and "
             "relaxing at rest over %.0f s (two assumed values). The standard states about "
             "+-50 %% for an unknown soil.",
             d.texture_factor, d.a_N_per_cm, d.b_N_per_cm_kmh, d.c_N_per_cm_kmh2,
             soil::kDraftReferenceDepth_mm, d.depth_exponent, d.mobilisation_mm,
             d.rest_relaxation_s),
      format("The soil wheel (radius %.3f m) slips %.1f +- %.1f %%; the board's wheel radius is "
             "the calibrated effective rolling radius (true radius / (1 - mean slip)).",
             p.soil.wheel_radius_m, p.soil.slip_mean_pct, p.soil.slip_variation_pct),
      effects(p.effects),
      format("Sigma statistics use samples with true (or measured) ground speed above %.2f m/s.",
             kSigmaMinSpeedMps),
  };
}

}  // namespace planter::sim
