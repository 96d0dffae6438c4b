#pragma once
// The reduced-order force model fitted to DEM compression curves across seedling diameters
// (the paper's 8.3-11.4 mm), for the plant model: see sim/seedling/seedling_force_model.h.
#include <functional>
#include <string>
#include <vector>

#include "dem/compression_report.h"
#include "sim/seedling/seedling_force_model.h"

namespace planter::dem {

struct DiameterCurve {
  double diameter_mm = 0.0;
  CompressionResult result;
  double fit_rms_N = 0.0;  // of the elastic branch fit for this diameter
};

struct ReducedOrderFit {
  sim::SeedlingForceModel model;
  std::vector<DiameterCurve> curves;
  double damping_runs_speedups[2] = {0.0, 0.0};
};

// Fits n (shared), k, F_p and delta_p per diameter, their linear trend in d, the collapse
// share, and c from two loading speeds at the reference diameter. `jobs` runs at once.
// `on_run_done(done, total)` is told as each compression ends (one call at a time): for progress.
ReducedOrderFit fit_reduced_order(
    const CompressionSetup& base, const std::vector<double>& diameters_mm, int jobs,
    const std::function<void(std::size_t done, std::size_t total)>& on_run_done = {});
// The model as the TOML file the scenario's [seedlings] force_model names.
std::string reduced_order_toml(const ReducedOrderFit& fit, const std::string& source);

}  // namespace planter::dem
