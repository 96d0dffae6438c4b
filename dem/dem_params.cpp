#include "dem/dem_params.h"

#include <array>
#include <charconv>
#include <cstdio>

#include "config/toml_section.h"
#include "dem/dem_keys.h"

namespace planter::dem {
namespace {

consteval const config::ConfigKey& dk(std::string_view dotted) {
  return config::key_in(kDemBodyKeys, dotted);
}

// The rows of material_rows(), in their order.
void read_material(config::TomlSection& t, const std::array<config::ConfigKey, 5>& rows,
                   ContactMaterial& m) {
  m.shear_modulus_Pa = t.number(rows[0]);
  m.poisson = t.number(rows[1]);
  m.restitution = t.number(rows[2]);
  m.friction = t.number(rows[3]);
  m.rolling_friction = t.number(rows[4]);
  t.reject_unknown_keys();
}

// The shortest text that reads back to the same double: a run read from its file is the run
// that was planned (calibration_runs.h), and the DEM is chaotic enough that a 6-digit rounding
// of one restitution moves the first peak by 0.5 % (measured: 0.413181 -> 0.413182).
std::string num(double v) {
  std::array<char, 32> b{};
  const auto r = std::to_chars(b.data(), b.data() + b.size(), v);
  return {b.data(), r.ptr};
}

std::string material_toml(const char* name, const ContactMaterial& m) {
  return std::string("[") + name + "]\nshear_modulus_Pa = " + num(m.shear_modulus_Pa) +
         "\npoisson = " + num(m.poisson) + "\nrestitution = " + num(m.restitution) +
         "\nfriction = " + num(m.friction) + "\nrolling_friction = " + num(m.rolling_friction) +
         "\n\n";
}

}  // namespace

CompressionSetup load_compression_setup(const std::string& path) {
  config::TomlDocument doc(path, {config::FileKind::kDemSetup, kDemFileKeys});
  config::TomlSection root = doc.root();
  // An empty file would run the paper's defaults while the user believes their file was used.
  if (root.keys().empty()) {
    throw config::ConfigError(path, 1, "",
                              "holds no parameters (tables seedling, material, bonds, contacts, "
                              "test); leave --params out to run the defaults");
  }
  CompressionSetup s;
  if (auto t = root.table("seedling")) {
    SeedlingGeometry& g = s.seedling;
    g.length_m = 1e-3 * t->number(dk("seedling.length_mm"));
    g.diameter_m = 1e-3 * t->number(dk("seedling.diameter_mm"));
    g.particle_radius_m = 1e-3 * t->number(dk("seedling.particle_radius_mm"));
    g.layers = static_cast<int>(t->integer(dk("seedling.layers")));
    g.density_kg_m3 = t->number(dk("seedling.density_kg_m3"));
    g.bond_gap_m = 1e-3 * t->number(dk("seedling.bond_gap_mm"));
    g.curvature_radius_m = 1e-3 * t->number(dk("seedling.curvature_radius_mm"));
    if (g.curvature_radius_m > 0.0 && g.curvature_radius_m < g.length_m / 3.0)
      t->fail(dk("seedling.curvature_radius_mm"),
              "must be 0 (straight) or at least a third of length_mm");
    if (2.0 * g.particle_radius_m > 0.5 * g.diameter_m)
      t->fail(dk("seedling.particle_radius_mm"), "must be at most a quarter of diameter_mm");
    t->reject_unknown_keys();
  }
  if (auto t = root.table("bond")) {
    BondParameters& b = s.bonds;
    b.normal_stiffness_N_m3 = t->number(dk("bond.normal_stiffness_N_m3"));
    b.shear_stiffness_N_m3 = t->number(dk("bond.shear_stiffness_N_m3"));
    b.tensile_strength_Pa = t->number(dk("bond.tensile_strength_Pa"));
    b.shear_strength_Pa = t->number(dk("bond.shear_strength_Pa"));
    b.radius_m = 1e-3 * t->number(dk("bond.radius_mm"));
    t->reject_unknown_keys();
  }
  if (auto t = root.table("seedling_contact"))
    read_material(*t, kSeedlingContactKeys, s.seedling_material);
  if (auto t = root.table("platen_contact"))
    read_material(*t, kPlatenContactKeys, s.platen_material);
  if (auto t = root.table("test")) {
    s.platen_speed_mps = t->number(dk("test.platen_speed_m_min")) / 60.0;
    s.speedup = t->number(dk("test.speedup"));
    s.time_step_s = t->number(dk("test.time_step_s"));
    s.stroke_m = 1e-3 * t->number(dk("test.stroke_mm"));
    s.local_damping = t->number(dk("test.local_damping"));
    s.samples = static_cast<int>(t->integer(dk("test.samples")));
    if (s.stroke_m >= s.seedling.diameter_m)
      t->fail(dk("test.stroke_mm"), "must be less than the seedling's diameter");
    t->reject_unknown_keys();
  }
  root.reject_unknown_keys();
  return s;
}

std::string compression_setup_toml(const CompressionSetup& s) {
  const SeedlingGeometry& g = s.seedling;
  const BondParameters& b = s.bonds;
  std::string out = "[seedling]\nlength_mm = " + num(1e3 * g.length_m) +
                    "\ndiameter_mm = " + num(1e3 * g.diameter_m) +
                    "\nparticle_radius_mm = " + num(1e3 * g.particle_radius_m) +
                    "\nlayers = " + std::to_string(g.layers) +
                    "\ndensity_kg_m3 = " + num(g.density_kg_m3) +
                    "\nbond_gap_mm = " + num(1e3 * g.bond_gap_m) +
                    "\ncurvature_radius_mm = " + num(1e3 * g.curvature_radius_m) + "\n\n";
  out += "[bond]\nnormal_stiffness_N_m3 = " + num(b.normal_stiffness_N_m3) +
         "\nshear_stiffness_N_m3 = " + num(b.shear_stiffness_N_m3) +
         "\ntensile_strength_Pa = " + num(b.tensile_strength_Pa) +
         "\nshear_strength_Pa = " + num(b.shear_strength_Pa) +
         "\nradius_mm = " + num(1e3 * b.radius_m) + "\n\n";
  out += material_toml("seedling_contact", s.seedling_material);
  out += material_toml("platen_contact", s.platen_material);
  out += "[test]\nplaten_speed_m_min = " + num(s.platen_speed_mps * 60.0) +
         "\nspeedup = " + num(s.speedup) + "\ntime_step_s = " + num(s.time_step_s) +
         "\nstroke_mm = " + num(1e3 * s.stroke_m) + "\nlocal_damping = " + num(s.local_damping) +
         "\nsamples = " + std::to_string(s.samples) + "\n";
  return out;
}

}  // namespace planter::dem
