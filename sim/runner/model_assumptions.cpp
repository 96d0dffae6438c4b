#include "sim/runner/model_assumptions.h"

#include <cstdio>

#include "config/stem_strength.h"
#include "sim/plant/effect_keys.h"
#include "sim/plant/seedling_process.h"
#include "sim/plant/seedling_release.h"
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

// The nip with the DEM's reduced law (sim/plant/clamp_nip.h), the specimen length's effect and
// the ceiling the same rule gives.
std::string nip_law(const PlantConfig& p, const config::BoardConfig& board) {
  const SeedlingConfig& c = p.seedlings;
  const double d_lo = c.diameter_min_mm, d_hi = c.diameter_max_mm, d_ref = c.reference_diameter_mm;
  // The nip's force at which a stem passes its first peak: its strength at the nip's scale.
  auto peak_at_nip = [&](double d, double z, double test_length_mm) {
    PlantConfig q = p;
    q.seedlings.strength_test_length_mm = test_length_mm;
    return config::lognormal_strength_N(c.strength_mean(), c.strength_sd(), z) *
           strength_size_factor(c, d) / nip_load_factor(q, d);
  };
  // The weakest diameter's first percentile: a thicker stem is held over less of its length.
  constexpr double kFirstPercentileZ = -2.3263;
  double ceiling_rule_N = 1e9, weakest_d = d_lo;
  for (int i = 0; i <= 20; ++i) {
    const double d = d_lo + (d_hi - d_lo) * i / 20.0;
    if (const double f = peak_at_nip(d, kFirstPercentileZ, c.strength_test_length_mm);
        f < ceiling_rule_N) {
      ceiling_rule_N = f;
      weakest_d = d;
    }
  }
  const double dem_specimen_mm = 190.0;  // dem/seedling.h: the DEM's modelled stem
  return format(
      "The nip is the lips in series with the stem (sim/plant/clamp_nip.h): the DEM's reduced law "
      "(%s) gives each stem's compression, so the load cell reads its thickness, stiffness and "
      "collapse, and a stem is damaged when the force through it passes its first peak. Its peak: "
      "the measured strength times (d / %.0f mm)^%.2g (assumed: the law's own slope of the peak "
      "with d comes from the DEM's particle scaling), at the nip's scale held length / %.0f mm "
      "(the strength test's specimen length, "
      "assumed: at the DEM's own %.0f mm stem the reference stem's median peak in the nip would be "
      "%.0f N, far below the paper's 90 N field grip that damaged 2.76 %%, so the test's loaded "
      "length was short). By the same rule 1 %% of this scenario's weakest stems (%.1f mm) pass "
      "their peak at %.0f N through the nip. The machine's %s; a thicker stem's own ceiling is "
      "lower by its held length (the clamp applies it per stem).",
      c.force_model_file.c_str(), d_ref, c.strength_diameter_exponent, c.strength_test_length_mm,
      dem_specimen_mm, peak_at_nip(d_ref, 0.0, dem_specimen_mm), weakest_d, ceiling_rule_N,
      config::clamp_ceiling_derivation(board.clamp_ceiling,
                                       board.controller.clamp.stem.reference_diameter_mm)
          .c_str());
}

std::string strength(const PlantConfig& p, const config::BoardConfig& board) {
  const SeedlingConfig& c = p.seedlings;
  const config::StrengthFit& m = config::measured_strength();
  const std::string measured = format(
      "Seedling strength: lognormal with mean %.1f N and SD %.1f N (the paper's six measured "
      "peaks, Sec. 3.5, are %.1f-%.1f N with mean %.1f N, SD %.1f N, the mean's 95 %% interval "
      "%.1f-%.1f N; its text's %.1f N is shown for comparison only); the lognormal form is "
      "assumed, as six values cannot choose it. ",
      c.strength_mean(), c.strength_sd(), m.min_N, m.max_N, m.mean_N, m.sd_N, m.mean_lo_N,
      m.mean_hi_N, config::kPaperStatedStrength_N);
  if (!c.force_model.loaded)
    return measured +
           format(
               "Strength ~ (diameter / %.0f mm)^%.2g (assumed). A seedling is damaged when the "
               "nip's line load (clamp force over the held length, contact area / diameter, at "
               "most the %.0f mm band) exceeds the test's (its strength over %.0f mm, assumed).",
               c.reference_diameter_mm, c.strength_diameter_exponent,
               p.mechanism.protrusion_band_mm, c.strength_test_length_mm);
  return measured + nip_law(p, board);
}

std::string effects(const Effects& e) {
  std::string on;
  for (const EffectKey& k : kEffectKeys) {
    const double v = e.*k.member;
    if (v == k.fallback) continue;
    on += format("%s%s = %g %s (%s)", on.empty() ? "" : "; ", k.key, v, k.unit, k.what);
  }
  if (on.empty())
    return "Hidden effects: none; the plant is the nominal structure of docs/recording-format.md.";
  return "Hidden effects on (the [effects] table): " + on + ".";
}

}  // namespace

std::vector<std::string> model_assumptions(const Scenario& sc) {
  const PlantConfig& p = sc.plant;
  const soil::OpenerDraftLaw& d = p.soil.draft;
  const MechanismConfig& m = p.mechanism;
  const DriveModelConfig& dr = p.drive;
  return {
      strength(p, sc.board),
      format("Contact area acts through mechanics: the lips hold the stem over contact area / "
             "diameter (%.0f mm^2 here: %.1f mm of a 10 mm stem, at most the %.0f mm band), which "
             "spreads the nip's load (damage) and sets the friction moment that keeps the "
             "seedling from turning in the clamp. Nothing in the model penalises a large area (the "
             "paper's rigid-disc contact is not modelled), so the model's best area is at the top "
             "of any range it is given.",
             m.contact_area_mm2, held_length_m(m, 10.0) * 1e3, m.protrusion_band_mm),
      format("Tilt from the release mechanics (sim/plant/seedling_release.h): a rigid seedling "
             "(density %.1f kg/m^3) held radially, root end %.0f mm beyond the rim; the disc rides "
             "with the opener (the paper, Fig. 2), the root end's lowest point %.0f mm above the "
             "furrow floor. Carried by friction on both lip faces (mu %.2f, the paper's 0.2-0.3); "
             "the root plowed through the returned soil turns it in the clamp when the soil's "
             "moment beats mu N w / 2 (before that the lips turn with it, their rubber in shear: G "
             "%.2f MPa over %.0f mm), and slides it along the clamp when the soil's push beats "
             "2 mu N; released %.1f deg past the lowest point, the leaves dragged by the lips with "
             "%.3f of the clamp force until the top leaves the disc, against the root's anchorage "
             "in c-phi soil (Broms' short pile with Rankine-Bell's passive pressure: returned soil "
             "%.1f kN/m^3, phi %.0f deg, c %.1f kPa); it falls under its weight where that beats "
             "the returned soil, until the covering wheel (%.0f mm behind) fills and firms the "
             "furrow (%.1f kN/m^3, c %.1f kPa) and holds it where it is, or it lodges. Every value "
             "and its source: the table of model values. Calibrated to the paper's centre point "
             "(1 value): the scatter the stages leave out, %.1f deg. Uprightness = mean of (1 - "
             "|tilt| / 90 deg), the paper's definition.",
             p.seedlings.density_kg_per_m3, m.root_protrusion_mm, m.root_clearance_mm,
             m.lip_friction, m.lip_shear_modulus_MPa, m.lip_shear_layer_mm,
             m.release_after_lowest_deg, m.residual_grip_share,
             p.soil.backflow.unit_weight_kN_per_m3, p.soil.backflow.friction_angle_deg,
             p.soil.backflow.cohesion_kPa, m.covering_wheel_behind_mm,
             p.soil.firmed.unit_weight_kN_per_m3, p.soil.firmed.cohesion_kPa,
             p.seedlings.tilt_noise_deg),
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
