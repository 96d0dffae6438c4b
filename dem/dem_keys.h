#pragma once
// The keys of planter-dem's parameter file (--params), declared once (config/config_key.h).
// The loader (dem/dem_params.cpp) reads through these rows; `planter-dem --list-keys` and
// docs/configuration.md print them. Defaults come from the structs in dem/, in the file's units.
#include <array>

#include "config/config_key.h"
#include "dem/compression_test.h"

namespace planter::dem {

using config::integer_key;
using config::number_key;
using config::FileKind::kDemSetup;

// The two contact tables hold the same five keys, each with its own defaults.
constexpr std::array<config::ConfigKey, 5> material_rows(std::string_view table,
                                                         const ContactMaterial& m) {
  return {number_key(kDemSetup, table, "shear_modulus_Pa", m.shear_modulus_Pa, 1e3, 1e12, "Pa",
                     "the shear modulus G of the Hertz-Mindlin contact"),
          number_key(kDemSetup, table, "poisson", m.poisson, 0.0, 0.499, "", "Poisson's ratio"),
          number_key(kDemSetup, table, "restitution", m.restitution, 0.01, 1.0, "",
                     "the coefficient of restitution"),
          number_key(kDemSetup, table, "friction", m.friction, 0.0, 5.0, "",
                     "the static friction coefficient"),
          number_key(kDemSetup, table, "rolling_friction", m.rolling_friction, 0.0, 1.0, "",
                     "the rolling friction coefficient (EDEM's type A)")};
}

// clang-format off
inline constexpr config::ConfigKey kDemBodyKeys[] = {
  number_key(kDemSetup, "seedling", "length_mm", 1e3 * SeedlingGeometry{}.length_m, 5.0, 400.0, "mm", "the modelled stem's length"),
  number_key(kDemSetup, "seedling", "diameter_mm", 1e3 * SeedlingGeometry{}.diameter_m, 3.0, 30.0, "mm", "its diameter"),
  number_key(kDemSetup, "seedling", "particle_radius_mm", 1e3 * SeedlingGeometry{}.particle_radius_m, 0.3, 5.0, "mm", "the particles' radius (at most a quarter of the diameter)"),
  integer_key(kDemSetup, "seedling", "layers", SeedlingGeometry{}.layers, 1, 4, "", "concentric rings of particles in the wall"),
  number_key(kDemSetup, "seedling", "density_kg_m3", SeedlingGeometry{}.density_kg_m3, 100.0, 3000.0, "kg/m^3", "the stem's density"),
  number_key(kDemSetup, "seedling", "bond_gap_mm", 1e3 * SeedlingGeometry{}.bond_gap_m, 0.0, 3.0, "mm", "particles closer than 2 r + this are bonded"),
  number_key(kDemSetup, "seedling", "curvature_radius_mm", 1e3 * SeedlingGeometry{}.curvature_radius_m, 0.0, 1e5, "mm", "the stem's bend (0: straight, else at least a third of the length)"),
  number_key(kDemSetup, "bond", "normal_stiffness_N_m3", BondParameters{}.normal_stiffness_N_m3, 1e5, 1e12, "N/m^3", "the parallel bond's normal stiffness per area"),
  number_key(kDemSetup, "bond", "shear_stiffness_N_m3", BondParameters{}.shear_stiffness_N_m3, 1e5, 1e12, "N/m^3", "its shear stiffness per area"),
  number_key(kDemSetup, "bond", "tensile_strength_Pa", BondParameters{}.tensile_strength_Pa, 1e2, 1e10, "Pa", "the stress a bond breaks at in tension"),
  number_key(kDemSetup, "bond", "shear_strength_Pa", BondParameters{}.shear_strength_Pa, 1e2, 1e10, "Pa", "the stress a bond breaks at in shear"),
  number_key(kDemSetup, "bond", "radius_mm", 1e3 * BondParameters{}.radius_m, 0.1, 10.0, "mm", "the bond's radius"),
  number_key(kDemSetup, "test", "platen_speed_m_min", CompressionSetup{}.platen_speed_mps * 60.0, 0.001, 10.0, "m/min", "the platen's speed before the speed-up (the paper's 0.2 m/min)"),
  number_key(kDemSetup, "test", "speedup", CompressionSetup{}.speedup, 1.0, 500.0, "", "the platen speed's multiplier (1: the paper's)"),
  number_key(kDemSetup, "test", "time_step_s", CompressionSetup{}.time_step_s, 1e-8, 1e-4, "s", "the integration step"),
  number_key(kDemSetup, "test", "stroke_mm", 1e3 * CompressionSetup{}.stroke_m, 0.1, 20.0, "mm", "the platen's travel (less than the diameter)"),
  number_key(kDemSetup, "test", "local_damping", CompressionSetup{}.local_damping, 0.0, 0.9, "", "Cundall's local damping, keeping the fast loading quasi-static"),
  integer_key(kDemSetup, "test", "samples", CompressionSetup{}.samples, 10, 100000, "", "points on the force-displacement curve"),
};
// clang-format on

inline constexpr auto kSeedlingContactKeys =
    material_rows("seedling_contact", CompressionSetup{}.seedling_material);
inline constexpr auto kPlatenContactKeys =
    material_rows("platen_contact", CompressionSetup{}.platen_material);

inline constexpr std::span<const config::ConfigKey> kDemFileKeys[] = {
    kDemBodyKeys, kSeedlingContactKeys, kPlatenContactKeys};

}  // namespace planter::dem
