#pragma once
// The paper's radial compression test: the seedling lies on a fixed lower platen and an upper
// platen comes down on it at the loading speed. Speeding the platen up is the usual shortcut
// (the paper's 0.2 m/min needs ~1e6 steps); the result carries the speed used and the largest
// kinetic-to-work ratio, so a run that was too fast to be quasi-static says so.
#include <functional>
#include <string>
#include <vector>

#include "dem/material.h"
#include "dem/seedling.h"

namespace planter::dem {

struct CompressionSetup {
  SeedlingGeometry seedling;
  ContactMaterial seedling_material;
  ContactMaterial platen_material{.shear_modulus_Pa = 7.9e10,
                                  .poisson = 0.30,
                                  .restitution = 0.45,
                                  .friction = 0.5,
                                  .rolling_friction = 0.05};
  BondParameters bonds;
  double platen_speed_mps = 0.2 / 60.0;  // the paper's 0.2 m/min
  double speedup = 50.0;                 // platen speed multiplier (1 = the paper's)
  double time_step_s = 2e-6;
  double stroke_m = 6e-3;
  double local_damping = 0.1;        // Cundall damping; keeps the fast loading quasi-static
  int samples = 300;                 // points on the force-displacement curve
  double peak_drop_fraction = 0.05;  // a first peak is a maximum the force then falls 5 % from
};

struct CurvePoint {
  double displacement_m = 0.0;
  double force_N = 0.0;  // upper platen, mean over the sample interval
  int broken_bonds = 0;
};

struct CompressionResult {
  std::vector<CurvePoint> curve;
  double peak_force_N = 0.0;
  double peak_displacement_m = 0.0;
  bool first_peak_found = false;  // false: no drop after the maximum within the stroke
  // The collapse: the peak with the largest fall after it (smoothed). The first peak can be a
  // small drop (a few bonds) before the tube's collapse, which the chart shows higher; both
  // are reported and marked. 0 when the force never falls.
  double collapse_force_N = 0.0;
  double collapse_displacement_m = 0.0;
  double collapse_drop_N = 0.0;
  int broken_bonds = 0;
  int particles = 0;
  int bonds = 0;
  long steps = 0;
  double max_kinetic_to_work = 0.0;  // largest kinetic energy / platen work after 10 % stroke
};

// The test's world before the first step: seedling, lower platen and the moving upper one.
struct CompressionWorld {
  DemWorld world;
  SeedlingBuild seedling;
  int upper_platen = 0;
  double platen_speed_mps = 0.0;  // with the speed-up
};
CompressionWorld make_compression_world(const CompressionSetup& setup);

// Runs the test; deterministic for a given setup.
// `threads` share each step (DemWorld::set_threads): the same result on any number.
// `on_sample`, when set, is told each point of the curve as it is made (progress on a terminal).
CompressionResult run_compression(const CompressionSetup& setup, int threads = 1,
                                  const std::function<void(const CurvePoint&)>& on_sample = {});
// The number of time steps run_compression takes: the stroke at the platen's (sped-up) speed.
[[nodiscard]] long compression_steps(const CompressionSetup& setup);

// The first peak of a curve (or its maximum when the force never falls by `drop_fraction`).
void find_first_peak(CompressionResult& r, double drop_fraction);
// Sets the collapse_* fields from the curve.
void find_collapse(CompressionResult& r);
// "153.0 N at 3.24 mm", or "none: the force never falls within the stroke".
std::string collapse_text(const CompressionResult& r);

}  // namespace planter::dem
