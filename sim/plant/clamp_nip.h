#pragma once
// The roller's nip: the disc's lips in series with the stem they hold (issue 50).
//
// The machine's clamp law F = k (x - x0)^n (docs/configuration.md, clamp_k_N) is the clamp as
// calibrated with a stem of the reference diameter in the nip, so it holds the reference stem's
// compliance. Another stem changes the gap two ways: its thickness closes it by
// g (d - d_ref) (seedling_thickness_gain), and its compliance opens it by the difference of the
// two stems' compressions at the force that passes through both (springs in series carry one
// force and add their deflections: Timoshenko and Goodier, Theory of Elasticity, ch. 1). So
//     F = k (x - x0 + g (d - d_ref) - [delta_d(F) - delta_ref(F)])^n,
// solved for F each step. A stem's compression in the nip is the DEM's reduced law
// (planter-dem reduce, sim/seedling/seedling_force_model.h) scaled from the strength test's
// specimen to the nip's held length: the nip and the test load the wall at the same line load
// (nip_load_factor, seedling_process.h), so delta_d(F) = (F / (a k(d)))^(1/m) with a = w / L_test.
// The stem's first peak P (its strength at the nip's scale) is where its wall collapses: past it
// the stem carries the DEM's residual share r P at the peak's compression and stiffens again
// from there (the DEM's curve after its drop densifies, models/seedling_dem.toml; the form of
// that rise is assumed: the intact law from the peak's compression). The force through the nip
// then drops: the load cell sees the collapse. The DEM's damping term (1e-4 N s/mm) is left out.
// While the lips close on the stem and open again, what it adds comes in and goes out in
// proportion (NipStem::share). An empty nip reads the law at g (d - d_ref) = 0, as a reference stem
// would: the lips' own law alone is not known apart from the calibration (docs/simulator.md).
#include "sim/seedling/seedling_force_model.h"

namespace planter::sim {

// One stem in the nip, as the law needs it.
struct NipStem {
  double diameter_mm = 0.0;
  double load_factor = 1.0;  // a = w / L_test: the nip's force per unit of the test's force
  double peak_N = 0.0;       // its first peak at the nip's scale (a times its strength)
  bool collapsed = false;    // its wall has passed the first peak
  // How far the lips have closed on it (0-1): what it adds to the law's compression, thickness
  // and compliance alike, and the share of the nip's force it carries (the rest passes from lip
  // to lip beside it), while it comes under the roller and leaves (assumed linear:
  // mechanism.nip_entry_mm).
  double share = 1.0;
};

class ClampNip {
 public:
  // `reference_load_factor`: a for the reference stem.
  ClampNip(const SeedlingForceModel& law, double reference_diameter_mm,
           double reference_load_factor, double thickness_gain)
      : law_(law),
        ref_d_mm_(reference_diameter_mm),
        ref_a_(reference_load_factor),
        gain_(thickness_gain) {}

  // The force (N) through the nip at the law's compression `gap_mm` = x - x0 (before the stem's
  // thickness), with clamp law k_N, n; `stem` may collapse (its flag is set). `guess_N` starts
  // the solve (the last step's force).
  [[nodiscard]] double force_N(double gap_mm, double k_N, double n, NipStem& stem,
                               double guess_N) const;
  // What the stem adds to the law's compression at force F: g (d - d_ref) - [delta_d - delta_ref]
  // (the recording's known_nip_mm, with which the machine's law gives F exactly).
  [[nodiscard]] double added_compression_mm(const NipStem& stem, double force_N) const;
  // The stem's compression at force F (mm): the intact branch, or past its collapse.
  [[nodiscard]] double stem_compression_mm(const NipStem& stem, double force_N) const;

 private:
  struct Compression {
    double mm;
    double mm_per_N;
  };
  [[nodiscard]] Compression stem_compression(const NipStem& stem, double force_N) const;
  [[nodiscard]] double intact_compression_mm(double d_mm, double a, double force_N) const;

  SeedlingForceModel law_;
  double ref_d_mm_;
  double ref_a_;
  double gain_;
};

}  // namespace planter::sim
