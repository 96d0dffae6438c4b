#include "analysis/named_disturbance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/residual_stats.h"

namespace planter::analysis {
namespace {

std::optional<DisturbanceFit> fitted_beside(const ChannelModel& ch, const DisturbanceSpec& spec,
                                            const Recording& r, const std::vector<double>& s_m,
                                            const Split& split, const ChannelFit& fit,
                                            const DisturbanceFit* near = nullptr) {
  const std::vector<double> gain = ch.disturbance_gain(r, fit.nominal, fit.prediction);
  return fit_disturbance(spec, gain, s_m, residual_of(fit.prediction, r.at(ch.output())),
                         split.calibration_end, near);
}

// Why the process does not earn its place, or "" when it does.
std::string rejection(const DisturbanceFit& d, double held_out_rms, const FitOptions& o) {
  char buf[240];
  if (d.delta_bic >= -o.min_delta_bic) return bic_shortfall(d.delta_bic, o.min_delta_bic);
  if (!(d.rms >= 2.0 * d.rms_sd)) {
    std::snprintf(buf, sizeof buf, "its size, %.3g, is within two SD (%.2g) of none", d.rms,
                  d.rms_sd);
    return buf;
  }
  // A process shorter than a row's travel is white noise to these rows, not a process along
  // the row (a noisy ground speed read as a slip 2 mm long).
  if (d.scale_m < d.step_m) {
    std::snprintf(buf, sizeof buf,
                  "its scale along the row, %.3g m, is under a row's travel (%.3g m): noise, "
                  "not a process the rows resolve",
                  d.scale_m, d.step_m);
    return buf;
  }
  const double gain = held_out_rms > 0.0 ? 1.0 - d.rms_held_out / held_out_rms : 0.0;
  if (gain < o.min_improvement) {
    std::snprintf(buf, sizeof buf,
                  "its one-step predictions lower the held-out RMS by %.1f %%; %.0f %% is "
                  "required",
                  100.0 * gain, 100.0 * o.min_improvement);
    return buf;
  }
  return "";
}

// The relative SD of the gain's size (its RMS over the calibration rows) from the nominal
// parameters' covariance (first order): a process read through a law (the stems through the
// clamp law's slope) is known no better than that law's slope.
double gain_relative_sd(const ChannelModel& ch, const Recording& r, const ChannelFit& fit,
                        std::size_t end) {
  const std::size_t m = fit.nominal.size();
  if (fit.nominal_covariance.size() != m * m) return 0.0;
  auto size_of = [&](const std::vector<double>& nominal) {
    const std::vector<double> g = ch.disturbance_gain(r, nominal, fit.prediction);
    double sum = 0.0;
    for (std::size_t k = 0; k < std::min(end, g.size()); ++k) sum += g[k] * g[k];
    return std::sqrt(sum / static_cast<double>(std::max<std::size_t>(1, end)));
  };
  const double base = size_of(fit.nominal);
  if (!(base > 0.0)) return 0.0;
  std::vector<double> jac(m, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    std::vector<double> moved = fit.nominal;
    const double h = std::max(1e-7, 1e-4 * std::abs(moved[i]));
    moved[i] += h;
    jac[i] = (size_of(moved) - base) / h;
  }
  double var = 0.0;
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = 0; b < m; ++b) var += jac[a] * fit.nominal_covariance[a * m + b] * jac[b];
  return std::sqrt(std::max(0.0, var)) / base;
}

// Each effect chosen without the process must still earn its place beside it: a terrain read
// as a play between the depth drive and its load is the terrain.
void keep_effects_beside(ChannelReport& c, const Recording& r, const Split& split,
                         const FitOptions& o, const std::vector<double>& s_m,
                         std::optional<DisturbanceFit>& d) {
  const ChannelModel& ch = *c.channel;
  const DisturbanceSpec& spec = *d->spec;
  for (std::size_t i = c.final_fit.effects.size(); i-- > 0;) {
    std::vector<Effect> without = c.final_fit.effects;
    const std::string name = without[i].spec->name;
    without.erase(without.begin() + static_cast<std::ptrdiff_t>(i));
    ChannelFit fit_without =
        without.empty() ? c.nominal : fit_channel(ch, r, split, c.nominal.nominal, without);
    const std::optional<DisturbanceFit> dw =
        fitted_beside(ch, spec, r, s_m, split, fit_without, &*d);
    const double gain =
        dw && dw->rms_held_out > 0.0 ? 1.0 - d->rms_held_out / dw->rms_held_out : 1.0;
    if (gain >= o.min_improvement) continue;
    char buf[320];
    std::snprintf(
        buf, sizeof buf,
        "%s left out: beside the process (%s) it lowers the held-out one-step RMS by %.1f %% "
        "(%.4g -> %.4g); %.0f %% is required",
        name.c_str(), spec.name.c_str(), 100.0 * gain, dw->rms_held_out, d->rms_held_out,
        100.0 * o.min_improvement);
    c.beside_disturbance.emplace_back(buf);
    std::erase_if(c.chosen, [&](const Candidate& k) { return k.effect == name; });
    std::erase_if(c.ties, [&](const Tie& t) { return t.chosen == name; });
    c.final_fit = std::move(fit_without);
    d = dw;
  }
}

// A fit of the channel beside the held process, by its one-step innovations rather than by the
// free-run error the process distorts (a prediction-error fit), from `from`'s values.
ChannelFit fitted_by_innovations(const ChannelModel& ch, const Recording& r, const Split& split,
                                 const ChannelFit& from, const DisturbanceFit& held) {
  const ResidualFilter whiten = [&held](std::vector<double>& e) {
    standardised_innovations(held, e);
  };
  return fit_channel(ch, r, split, from.nominal, from.effects, &whiten);
}

// The nominal (and what effects stay) fitted again beside the process (a stems' spread left
// the clamp law's exponent at its range's edge), the process refitted on what that leaves;
// kept while the likelihood of the calibration rows rises, twice at most.
void refit_beside(ChannelReport& c, const Recording& r, const Split& split,
                  const std::vector<double>& s_m, std::optional<DisturbanceFit>& d) {
  for (int pass = 0; pass < 2; ++pass) {
    const DisturbanceFit held = *d;
    ChannelFit beside = fitted_by_innovations(*c.channel, r, split, c.final_fit, held);
    std::optional<DisturbanceFit> again =
        fitted_beside(*c.channel, *held.spec, r, s_m, split, beside, &held);
    if (!again || again->neg2ll >= d->neg2ll) break;
    c.final_fit = std::move(beside);
    d = std::move(again);
  }
}

// An effect the process hid (issue 52: a clamp's relaxation under the stems' spread). Judged
// without the process, its share of the residual and its left-out blocks are the process's as
// much as its own. A candidate that meets every other rule is fitted again by the process's
// innovations, the process refitted beside it, and named when its size is still two SD from
// none, the pair lowers BIC by min_delta_bic (its parameters counted) and the one-step held-out
// RMS by min_improvement: the rules a process and an effect kept beside it meet.
void seek_effect_beside(ChannelReport& c, const Recording& r, const Split& split,
                        const FitOptions& o, const std::vector<double>& s_m,
                        std::optional<DisturbanceFit>& d) {
  const std::size_t rows = split.calibration_end - std::min(split.calibration_end, d->shape.skip);
  for (const Candidate& k : c.ranked) {
    Candidate judged = k;  // every rule but the two the process spoils
    judged.explained = std::max(k.explained, o.min_explained);
    judged.cv_improvement = std::max(k.cv_improvement, o.min_improvement);
    if (!rejection(judged, o).empty()) continue;
    ChannelFit beside = fitted_by_innovations(*c.channel, r, split, k.fit, *d);
    std::optional<DisturbanceFit> dk =
        fitted_beside(*c.channel, *d->spec, r, s_m, split, beside, &*d);
    if (!dk) continue;
    // Its size beside the process, two SD from none, a delay's SD at least a row of the thinned
    // rows it is read on (it is not refined at the full rate beside a process, mismatch.cpp).
    judged.fit = beside;
    widen_delay_by_row(judged.fit, r);
    if (const std::string why = rejection(judged, o); !why.empty()) {
      c.beside_disturbance.push_back(k.effect + " beside the process: " + why + "; not named");
      continue;
    }
    const double params = static_cast<double>(k.fit.effects.back().values.size());
    const double delta_bic = dk->neg2ll - d->neg2ll +
                             params * std::log(static_cast<double>(std::max<std::size_t>(rows, 2)));
    const double gain = d->rms_held_out > 0.0 ? 1.0 - dk->rms_held_out / d->rms_held_out : 0.0;
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "%s beside the process: BIC %+.1f, held-out one-step RMS %+.1f %% (%.4g -> "
                  "%.4g)",
                  k.effect.c_str(), delta_bic, -100.0 * gain, d->rms_held_out, dk->rms_held_out);
    if (delta_bic >= -o.min_delta_bic || gain < o.min_improvement) {
      c.beside_disturbance.push_back(std::string(buf) + "; not named");
      continue;
    }
    c.beside_disturbance.push_back(std::string(buf) + "; named");
    c.one_step_nominal = d->rms_held_out;
    c.chosen.push_back(k);
    c.final_fit = std::move(beside);
    d = std::move(dk);
    return;
  }
}

// The process, named first, must still earn its place beside the effect then named with it
// (fitted without it), by the rules it meets beside effects chosen first: a recording that
// counts seedlings but holds a relaxation and no stems' spread to speak of named a process of
// 0.0018 mm beside it. Where it does not, it is said, and nothing of it is kept.
bool earns_beside(ChannelReport& c, const Recording& r, const Split& split, const FitOptions& o,
                  const std::vector<double>& s_m, const DisturbanceSpec& spec) {
  const ChannelFit& effect_alone = c.chosen.back().fit;
  const std::optional<DisturbanceFit> d =
      fitted_beside(*c.channel, spec, r, s_m, split, effect_alone);
  const std::string why = d ? rejection(*d, effect_alone.rms_held_out, o) : "no fit";
  if (why.empty()) return true;
  c.beside_disturbance.push_back(spec.name + " not named beside " + c.chosen.back().effect + ": " +
                                 why);
  c.chosen.clear();
  c.final_fit = c.nominal;
  return false;
}

}  // namespace

void name_disturbance(ChannelReport& c, const Recording& r, const Split& split,
                      const FitOptions& o) {
  const ChannelModel& ch = *c.channel;
  const DisturbanceSpec* spec = ch.disturbance(r);
  if (spec == nullptr) return;
  // Sought only where the nominal leaves more than the noise and the input's noise make (by
  // the factor a residual must exceed them to be unexplained): a noisy ground speed is no slip.
  const double floor =
      std::hypot(c.noise_rms, ch.input_noise_rms(r, c.nominal.nominal, split.calibration_end));
  if (!(c.nominal.rms_held_out > 3.0 * floor)) return;
  const std::vector<double> s_m = distance_travelled(r);
  std::optional<DisturbanceFit> d = fitted_beside(ch, *spec, r, s_m, split, c.final_fit);
  if (!d) return;
  if (const std::string why = rejection(*d, c.final_fit.rms_held_out, o); !why.empty()) {
    c.beside_disturbance.push_back(spec->name + " not named: " + why);
    return;
  }
  // Sought beside the process only where nothing was chosen without it: an effect chosen and
  // then left out beside the process was the process (a terrain read as a play), and so is its
  // tie (the play after the drive).
  const bool chosen_without = !c.chosen.empty();
  keep_effects_beside(c, r, split, o, s_m, d);
  refit_beside(c, r, split, s_m, d);
  if (!chosen_without) {
    seek_effect_beside(c, r, split, o, s_m, d);
    if (!c.chosen.empty()) {
      if (!earns_beside(c, r, split, o, s_m, *spec)) return;
      refit_beside(c, r, split, s_m, d);
    }
  }
  // The size's SD with the gain's own: the process is the residual over the gain.
  const double relative = gain_relative_sd(ch, r, c.final_fit, split.calibration_end);
  d->rms_sd = std::hypot(d->rms_sd, relative * d->rms);
  c.disturbance = d;
}

}  // namespace planter::analysis
