#pragma once
// What planter-fit writes: fit.json (the verdict, ranked effects with parameters, their
// uncertainty and evidence, held-out error before and after per channel), report.html
// (self-contained: overlays, residuals, where the mismatch was) and model.toml (the
// augmented model, which `planter-sim replay` runs).
#include <string>

#include "analysis/mismatch.h"
#include "config/output_set.h"

namespace planter::analysis {

std::string fit_json(const FitReport& r, double wall_s);
std::string fit_model_toml(const FitReport& r);
std::string fit_report_html(const FitReport& r, const Recording& rec);
// Writes all three into the output set, commits it (the old set or the new, never a mix) and
// returns fit.json's text; throws std::runtime_error naming a file that cannot be written.
std::string write_fit_outputs(config::OutputSet& out, const FitReport& r, const Recording& rec,
                              double wall_s);

}  // namespace planter::analysis
