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
// One effect of a channel as the summary and the report print it, with its parameters, their
// SDs and units ("relaxation of the clamp: fraction = 0.2987 +- 0.001, tau_s = 3.023 +- 0.011
// s"), and why when it is another effect seen from this channel.
// The held-out RMS the channel's final model leaves: its one-step predictions beside a named
// disturbance, else its free-run prediction's.
double held_out_after(const ChannelReport& c);
// The nominal parameters no fitted row exercised, with the values they were left at
// ("omega_max (at 0.511 rad/s)"), or "".
std::string not_exercised(const ChannelReport& c);
std::string effect_text(const ChannelReport& report, std::size_t effect);
std::string fit_model_toml(const FitReport& r);
std::string fit_report_html(const FitReport& r, const Recording& rec);
// Writes all three into the output set, commits it (the old set or the new, never a mix) and
// returns fit.json's text; throws std::runtime_error naming a file that cannot be written.
std::string write_fit_outputs(config::OutputSet& out, const FitReport& r, const Recording& rec,
                              double wall_s);

}  // namespace planter::analysis
