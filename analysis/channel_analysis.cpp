#include "analysis/channel_analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "analysis/effect_hooks.h"
#include "analysis/named_disturbance.h"
#include "analysis/residual_stats.h"

namespace planter::analysis {
namespace {

// Non-empty when the candidate's size is within two of its standard deviations of none (a grid
// parameter's SD is its step: one step from zero is not a size). Its fit's improvement is then
// the noise's, whatever BIC says: 'no verdict without its evidence' (issue 52).
std::string unresolved_size(const Candidate& c) {
  if (c.spec == nullptr || c.spec->size_param < 0) return "";
  const auto k = static_cast<std::size_t>(c.spec->size_param);
  const auto& fx = c.fit.effects;
  for (std::size_t e = 0; e < fx.size(); ++e) {
    if (fx[e].spec != c.spec || k >= fx[e].values.size()) continue;
    const double value = fx[e].values[k], sd = c.fit.effect_sd_of(e, k);
    if (!(sd > 0.0) || std::abs(value) >= 2.0 * sd) return "";
    char buf[200];
    std::snprintf(buf, sizeof buf, "its size, %s = %.4g %s, is within two SD (%.2g) of none",
                  c.spec->params[k].name.c_str(), value, c.spec->params[k].unit.c_str(), sd);
    return buf;
  }
  return "";
}

double correlation(const std::vector<double>& a, const std::vector<double>& b, std::size_t from,
                   std::size_t to, long lag) {
  double ma = 0, mb = 0;
  std::size_t n = 0;
  for (std::size_t k = from; k < to; ++k) {
    const long j = static_cast<long>(k) + lag;
    if (j < static_cast<long>(from) || j >= static_cast<long>(to)) continue;
    ma += a[k];
    mb += b[static_cast<std::size_t>(j)];
    ++n;
  }
  if (n < 3) return 0.0;
  ma /= static_cast<double>(n);
  mb /= static_cast<double>(n);
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t k = from; k < to; ++k) {
    const long j = static_cast<long>(k) + lag;
    if (j < static_cast<long>(from) || j >= static_cast<long>(to)) continue;
    const double x = a[k] - ma, z = b[static_cast<std::size_t>(j)] - mb;
    sab += x * z;
    saa += x * x;
    sbb += z * z;
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

Location locate(const ChannelModel& ch, const Recording& r, const std::vector<double>& e,
                std::size_t end, double noise_rms) {
  Location l;
  // Residual tests on the calibration part, thinned to at most 20000 samples.
  const std::size_t stride = std::max<std::size_t>(1, end / 20000);
  std::vector<double> et, ut, tt;
  const std::vector<double>* u = r.has(ch.input()) ? &r.at(ch.input()) : nullptr;
  for (std::size_t k = 0; k < end; k += stride) {
    et.push_back(e[k]);
    tt.push_back(r.t[k]);
    if (u) ut.push_back((*u)[k]);
  }
  const std::size_t n = et.size();
  l.whiteness_violations = whiteness_violations(et);
  if (u) {
    for (long lag = -20; lag <= 20; ++lag)
      l.input_correlation = std::max(l.input_correlation, std::abs(correlation(ut, et, 0, n, lag)));
  }
  l.time_correlation = correlation(tt, et, 0, n, 0);
  // Ten windows over the whole recording.
  std::vector<double> w_rms;
  const std::size_t total = e.size();
  for (int w = 0; w < 10; ++w) {
    const std::size_t a = total * w / 10, b = total * (w + 1) / 10;
    double s = 0;
    for (std::size_t k = a; k < b; ++k) s += e[k] * e[k];
    w_rms.push_back(std::sqrt(s / std::max<double>(1.0, static_cast<double>(b - a))));
  }
  std::vector<double> sorted = w_rms;
  std::sort(sorted.begin(), sorted.end());
  const auto worst = std::max_element(w_rms.begin(), w_rms.end()) - w_rms.begin();
  l.worst_window_start_s = r.t[total * static_cast<std::size_t>(worst) / 10];
  // Against the median window, but never below the noise: a window where the machine stands
  // still fits to nothing and would make any other look infinitely worse.
  const double typical = std::max(sorted[5], noise_rms);
  l.worst_window_ratio = typical > 0 ? w_rms[static_cast<std::size_t>(worst)] / typical : 0.0;
  // Regimes of the input and the load.
  auto regime = [&](const std::string& name, const std::vector<bool>& in) {
    double si = 0, so = 0;
    std::size_t ni = 0, no = 0;
    for (std::size_t k = 0; k < total; ++k) {
      if (in[k])
        si += e[k] * e[k], ++ni;
      else
        so += e[k] * e[k], ++no;
    }
    if (ni < 10 || no < 10) return;
    l.regimes.push_back({name,
                         std::sqrt(si / static_cast<double>(ni)) /
                             std::max(1e-12, std::sqrt(so / static_cast<double>(no))),
                         static_cast<double>(ni) / static_cast<double>(total)});
  };
  if (u) {
    const double span = signal_span(*u);
    std::vector<bool> near_zero(total), reversal(total, false), after_step(total, false);
    for (std::size_t k = 0; k < total; ++k) near_zero[k] = std::abs((*u)[k]) < 0.1 * span;
    regime("near zero " + ch.input(), near_zero);
    double last_sign = 0;
    for (std::size_t k = 1; k < total; ++k) {
      const double d = (*u)[k] - (*u)[k - 1];
      if (std::abs(d) < 1e-9 * span) continue;
      const double s = d > 0 ? 1 : -1;
      if (last_sign != 0 && s != last_sign)
        for (std::size_t j = k; j < total && r.t[j] - r.t[k] < 0.5; ++j) reversal[j] = true;
      last_sign = s;
      if (std::abs(d) > 0.05 * span)
        for (std::size_t j = k; j < total && r.t[j] - r.t[k] < 1.0; ++j) after_step[j] = true;
    }
    regime("at reversals of " + ch.input(), reversal);
    regime("after steps of " + ch.input(), after_step);
  }
  if (r.has("depth_force")) {
    std::vector<double> f = r.at("depth_force");
    std::vector<double> s = f;
    std::nth_element(s.begin(), s.begin() + static_cast<long>(3 * s.size() / 4), s.end());
    const double q3 = s[3 * s.size() / 4];
    std::vector<bool> high(total);
    for (std::size_t k = 0; k < total; ++k) high[k] = f[k] > q3 && q3 > 0;
    regime("at high draft load", high);
  }
  const Effect p = initial_effect(effect_spec(EffectKind::kPeriodic), r, e);
  l.dominant_amplitude = p.values[0];
  l.dominant_frequency_hz = p.values[1];
  return l;
}

// The zero-load rows an offset needs to be told from the nominal's constants: twenty rows fix
// a constant to about a quarter of the sensor's noise (1 / sqrt(20)).
constexpr std::size_t kOffsetZeroLoadRows = 20;

// The error the output's resolution alone leaves (residual_stats.h), from the grid its values
// lie on at the recording's own rate.
double output_resolution_rms(const Recording& r, const std::string& output) {
  const auto it = r.full_rate_grid.find(output);
  return resolution_rms(it != r.full_rate_grid.end() ? it->second : value_grid(r.at(output)));
}

// "the clamp law undetermined: k_c = 1.15 +- 233 N/mm^n, x0 = -13 +- 625 mm; ..." where the
// fit's nominal parameters are spread over a quarter of their range or more, or a positive one
// over its own value; "" where none is.
std::string degenerate_nominal(const ChannelModel& ch, const ChannelFit& fit) {
  const std::vector<ParamSpec> specs = ch.nominal_params();
  std::string list;
  for (std::size_t k = 0; k < specs.size() && k < fit.nominal_sd.size(); ++k) {
    const ParamSpec& p = specs[k];
    const double sd = fit.nominal_sd[k], v = fit.nominal[k];
    if (p.grid || p.of_output_size || !(sd > 0.0)) continue;
    const bool wide = p.upper > p.lower && sd >= 0.25 * (p.upper - p.lower);
    if (!wide && !(p.lower >= 0.0 && sd >= std::abs(v))) continue;
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s%s = %.4g +- %.3g %s", list.empty() ? "" : ", ",
                  p.name.c_str(), v, sd, p.unit.c_str());
    list += buf;
  }
  if (list.empty()) return "";
  return ch.law() + " undetermined: " + list + "; the recording does not move " + ch.input() +
         " over enough of its range to fix it";
}

// The analysis's state for one channel: what every step reads (the recording, the options, the
// split) and the report it fills.
class ChannelAnalysis {
 public:
  ChannelAnalysis(const ChannelModel& ch, const Recording& r, const FitOptions& o,
                  const Split& split)
      : ch_(ch), r_(r), o_(o), split_(split), y_(r.at(ch.output())), end_(split.calibration_end) {
    rep_.channel = &ch;
  }

  ChannelReport run() {
    step("its nominal model");
    measure_noise();
    fit_nominal();
    rank_effects();
    // Stems the machine counted through the nip are there: the residual is read as their spread
    // first, and an effect must earn its place beside it. Under the force loop the roller
    // follows each stem, so its history carries them, and effects chosen first read them as a
    // play and a hysteresis (the 10-minute field log: 2.46 -> 1.26 N held out) that each help
    // the other beside the process. Where the process does not earn its place, the effects are
    // chosen as anywhere.
    const bool process_first = ch_.disturbance(r_) != nullptr && ch_.disturbance_shown(r_);
    if (!process_first) choose_effects();
    judge_what_is_left();
    if (process_first && !rep_.disturbance) {
      // Why the process read first was not named stays in the report, before what follows.
      for (std::string& why : rep_.beside_disturbance) why = "read first (stems counted): " + why;
      rep_.chosen.clear();
      rep_.change.reset();
      rep_.final_fit = rep_.nominal;
      choose_effects();
      judge_what_is_left();
    }
    mark_range_edges();
    set_verdict();
    return std::move(rep_);
  }

 private:
  // What a candidate is judged against: the noise under a base fit (from its residual, so that
  // an effect already modelled, a vibration near the thinned Nyquist rate, no longer counts as
  // noise) and the base's blocked cross-validation errors.
  struct BaseFigures {
    double noise = 0.0;
    std::vector<double> fold_errors;
  };

  // The noise every comparison uses is at least what the output's resolution leaves: a coarse
  // sensor's rounding is no effect to name (hil-commissioning's draft, read in 2 N steps, named
  // a transport delay that bent the fit around a steady value's rounding; issue 32). Where the
  // rounding outweighs the noise at the recording's own rate, the steps are named as such.
  void measure_noise() {
    rep_.resolution_rms = output_resolution_rms(r_, ch_.output());
    rep_.noise_rms = std::max(white_noise_rms(y_, end_), rep_.resolution_rms);
    const auto full_noise = r_.full_rate_noise.find(ch_.output());
    const double white =
        full_noise != r_.full_rate_noise.end() ? full_noise->second : white_noise_rms(y_, end_);
    if (rep_.resolution_rms > 0.0 && rep_.resolution_rms >= white)
      rep_.logged_step = rep_.resolution_rms * std::sqrt(12.0);
  }

  // A model given with --model: its values start the fit and its effects are already known;
  // the search is for what is missing beyond them. The data's own rough guess starts the
  // nominal fit and, once more, each candidate; the channel's further starts are tried too.
  void fit_nominal() {
    const ModelChannel* given = nullptr;
    for (const auto& m : o_.start_model)
      if (m.channel == &ch_) given = &m;
    known_ = given ? given->effects : std::vector<Effect>{};
    data_guess_ = ch_.initial_guess(r_);
    rep_.nominal = fit_channel(ch_, r_, split_, given ? given->nominal : data_guess_, known_);
    for (const std::vector<double>& start : ch_.nominal_starts(r_)) {
      ChannelFit alt = fit_channel(ch_, r_, split_, start, known_);
      if (alt.bic < rep_.nominal.bic) rep_.nominal = std::move(alt);
    }
    rep_.location = locate(ch_, r_, residual_of(rep_.nominal.prediction, y_), end_, rep_.noise_rms);
  }

  // Earning its parameters: a clear BIC gain, half of the residual beyond noise explained,
  // a gain in blocked cross-validation (or on the held-out part), and no loss on the held-out
  // part. (Closed-loop records excite some effects only at starts and stops, so the held-out
  // part alone may not see them.) Blocked cross-validation: each of three contiguous
  // calibration blocks is left out in turn; base and candidate are refitted without it and
  // judged on it.
  std::vector<double> fold_errors(const ChannelFit& fit, double noise) const {
    std::vector<double> out;
    for (std::size_t b = 0; b < 3; ++b) {
      Split fold = split_;
      fold.fold_from = end_ * b / 3;
      fold.fold_to = end_ * (b + 1) / 3;
      // Below the noise a fold has nothing to gain or lose (a stretch at rest fits to zero).
      out.push_back(std::max(fold_rms(ch_, r_, fold, fit), noise));
    }
    return out;
  }

  // The best fold must gain, and no fold may lose: an effect excited only at a start or a stop
  // shows in one fold, but a wrong one costs somewhere else.
  double blocked_cv(const std::vector<double>& base_errors, const ChannelFit& with,
                    double noise) const {
    const std::vector<double> with_errors = fold_errors(with, noise);
    std::vector<double> gains;
    for (std::size_t b = 0; b < base_errors.size(); ++b)
      gains.push_back(base_errors[b] > 0 ? 1.0 - with_errors[b] / base_errors[b] : 0.0);
    std::sort(gains.begin(), gains.end());
    return gains.front() < -0.02 ? gains.front() : gains.back();
  }

  bool earns(const Candidate& c) const { return rejection(c, o_).empty(); }

  void step(const std::string& what) const {
    if (o_.on_step) o_.on_step(ch_.output(), what);
  }

  // A candidate's figures against the fit it would replace. The share of the residual beyond
  // the noise that the effect accounts for: a real mechanism explains the shape of what is
  // left, a wrong name only bends it a little. Its own part: the fit less the same fit without
  // what it adds to its base (one effect, or a pair judged together).
  void judge(const ChannelFit& base, const BaseFigures& figures, Candidate& c) const {
    c.delta_bic = c.fit.bic - base.bic;
    c.held_out_improvement =
        base.rms_held_out > 0 ? 1.0 - c.fit.rms_held_out / base.rms_held_out : 0.0;
    c.cv_improvement = blocked_cv(figures.fold_errors, c.fit, figures.noise);
    const double noise2 = figures.noise * figures.noise;
    const double before2 = base.rms_calibration * base.rms_calibration;
    const double after2 = c.fit.rms_calibration * c.fit.rms_calibration;
    c.explained = before2 > noise2 ? (before2 - after2) / (before2 - noise2) : 0.0;
    c.credited_rms = std::sqrt(std::max(0.0, before2 - after2));
    std::vector<Effect> without = c.fit.effects;
    std::erase_if(without, [&](const Effect& added) {
      return std::none_of(base.effects.begin(), base.effects.end(),
                          [&](const Effect& b) { return b.spec == added.spec; });
    });
    std::vector<double> alone;
    ch_.simulate(r_, c.fit.nominal, without, alone);
    c.own_rms = rms_between(c.fit.prediction, alone, 0, end_);
  }

  // The noise under a prediction: what its residual's second differences show, no more than
  // the recording's own, and no less than the output's resolution leaves.
  double noise_under(const std::vector<double>& prediction) const {
    return std::max(std::min(rep_.noise_rms, white_noise_rms(residual_of(prediction, y_), end_)),
                    rep_.resolution_rms);
  }

  BaseFigures figures_of(const ChannelFit& base) const {
    BaseFigures f;
    f.noise = noise_under(base.prediction);
    f.fold_errors = fold_errors(base, f.noise);
    return f;
  }

  // Whether `spec` is tried beside `start`: not twice, not beside an effect it holds or that
  // holds it (Stribeck and Coulomb), and a term that only makes sense beside another (a second
  // Prony term) waits for it.
  static bool tried_beside(const EffectSpec* spec, const std::vector<Effect>& start) {
    bool used = false, present = !spec->needs;
    for (const auto& s : start) {
      used =
          used || s.spec == spec || spec->extends == s.spec->kind || s.spec->extends == spec->kind;
      present = present || s.spec->kind == *spec->needs;
    }
    return !used && present;
  }

  // One candidate fitted beside `start`. The base fit may have bent its parameters to mimic
  // the effect (an offset looks like a contact point below the open clamp, relaxation like a
  // softer law): it starts once more from the data's own guess, and for relaxation from
  // several time constants. An offset that trades with the nominal's constants needs rows at
  // zero load.
  Candidate fitted_candidate(const EffectSpec* spec, const ChannelFit& base, std::vector<Effect> fx,
                             const std::vector<double>& base_e) const {
    fx.push_back(initial_effect(*spec, r_, base_e));
    Candidate c;
    c.spec = spec;
    c.effect = spec->name;
    c.fit = fit_channel(ch_, r_, split_, base.nominal, fx);
    // Beside a first effect, its located grid values are held in these further starts (the
    // data's guess beside a play refined five ways cost the field's clamp 6 s); the start from
    // the base refines them.
    const bool second = fx.size() > known_.size() + 1;
    if (ChannelFit alt = fit_channel(ch_, r_, split_, data_guess_, fx, nullptr, second);
        alt.bic < c.fit.bic)
      c.fit = std::move(alt);
    for (const std::vector<double>& values : spec->extra_starts) {
      fx.back().values = values;
      ChannelFit alt = fit_channel(ch_, r_, split_, data_guess_, fx, nullptr, second);
      if (alt.bic < c.fit.bic) c.fit = std::move(alt);
    }
    if (spec->kind == EffectKind::kOffset) {
      const std::optional<std::size_t> at_zero = ch_.zero_load_rows(r_, c.fit.nominal, end_);
      if (at_zero && *at_zero < kOffsetZeroLoadRows)
        c.not_separable =
            "cannot be told from the nominal's own constants: " + std::to_string(*at_zero) +
            " rows at zero load, " + std::to_string(kOffsetZeroLoadRows) + " needed; record " +
            spec->separating_experiment;
    }
    return c;
  }

  // Every candidate beside `start`, judged against `base`, best BIC first.
  std::vector<Candidate> try_effects(const ChannelFit& base, const BaseFigures& figures,
                                     const std::vector<Effect>& start) const {
    std::vector<Candidate> out;
    const std::vector<double> base_e = residual_of(base.prediction, y_);
    const std::vector<const EffectSpec*> specs = ch_.candidates(r_);
    for (std::size_t i = 0; i < specs.size(); ++i) {
      const EffectSpec* spec = specs[i];
      if (!tried_beside(spec, start)) continue;
      step((start.size() > known_.size() ? "beside " + start.back().spec->name + ", " : "") +
           spec->name + " (" + std::to_string(i + 1) + " of " + std::to_string(specs.size()) + ")");
      Candidate c = fitted_candidate(spec, base, start, base_e);
      judge(base, figures, c);
      out.push_back(std::move(c));
    }
    std::sort(out.begin(), out.end(),
              [](const Candidate& a, const Candidate& b) { return a.delta_bic < b.delta_bic; });
    return out;
  }

  // Of the candidates that earn their parameters, the one with the lowest held-out RMS; where
  // held-out errors tie (within FitOptions::held_out_tie of the lowest: an effect excited only
  // at starts and stops leaves the held-out part alike), the best BIC among them. Then
  // parsimony (simpler_of). Candidates that earn theirs and come within a BIC tie of the
  // chosen one are reported as ties.
  const Candidate* choose(const std::vector<Candidate>& cands) {
    double lowest_held_out = std::numeric_limits<double>::infinity();
    for (const auto& c : cands)
      if (earns(c)) lowest_held_out = std::min(lowest_held_out, c.fit.rms_held_out);
    const Candidate* best = nullptr;
    for (const auto& c : cands)
      if (earns(c) && c.fit.rms_held_out <= (1.0 + o_.held_out_tie) * lowest_held_out &&
          (!best || c.delta_bic < best->delta_bic))
        best = &c;
    best = simpler_of(best, cands);
    if (!best) return nullptr;
    for (const auto& c : cands) {
      if (&c == best || !earns(c) || c.delta_bic - best->delta_bic >= o_.tie_delta_bic) continue;
      const std::string& a = best->spec->separating_experiment;
      const std::string& b = c.spec->separating_experiment;
      rep_.ties.push_back(
          {best->effect, c.effect, c.delta_bic - best->delta_bic, a == b ? a : a + "; " + b});
    }
    return best;
  }

  // Parsimony: an effect that holds a simpler one (Stribeck holds Coulomb) gives way to it
  // unless it beats it clearly.
  const Candidate* simpler_of(const Candidate* best, const std::vector<Candidate>& cands) const {
    for (bool simpler = true; simpler && best && best->spec->extends;) {
      simpler = false;
      const Candidate* richer = best;
      for (const auto& c : cands)
        if (c.spec->kind == *richer->spec->extends && earns(c) &&
            (richer->delta_bic > c.delta_bic - o_.nested_delta_bic ||
             richer->explained < c.explained + o_.nested_min_explained)) {
          best = &c;
          simpler = true;
        }
    }
    return best;
  }

  // The best single effect by BIC that fails only on the share of the residual it explains,
  // with a quarter of it explained at least.
  const Candidate* partial(const std::vector<Candidate>& cands) const {
    for (const auto& c : cands) {
      if (!c.not_separable.empty() || c.explained < 0.25) continue;
      Candidate whole = c;
      whole.explained = o_.min_explained;
      if (earns(whole)) return &c;
    }
    return nullptr;
  }

  // Every candidate fitted beside the nominal and judged against it.
  void rank_effects() {
    nominal_figures_ = figures_of(rep_.nominal);
    rep_.ranked = try_effects(rep_.nominal, nominal_figures_, known_);
    rep_.final_fit = rep_.nominal;
  }

  // The best single effect and a second beside it; or, where none earns its place alone but
  // one fails only on its share, a pair judged together against the nominal.
  void choose_effects() {
    const BaseFigures& nominal_figures = nominal_figures_;
    if (const Candidate* best = choose(rep_.ranked)) {
      rep_.chosen.push_back(*best);
      rep_.final_fit = best->fit;
      const std::vector<Candidate> pairs =
          try_effects(best->fit, figures_of(best->fit), best->fit.effects);
      if (const Candidate* second = choose(pairs)) {
        rep_.chosen.push_back(*second);
        rep_.final_fit = second->fit;
        order_prony_terms(rep_.final_fit.effects, rep_.final_fit.effect_sd);
      }
    } else if (const Candidate* part = partial(rep_.ranked)) {
      choose_pair(*part, nominal_figures);
    }
  }

  // One effect explains part of the residual and fails only on that share: a second one may
  // explain the rest (a play with an offset). The pair is judged against the nominal as one
  // candidate, by the same rules (issue 32, item 4), and must not lose on any left-out block
  // (a single effect may, where the held-out part shows its gain): with a changed parameter
  // left unmodelled, a drift and an offset together fitted half of the residual and lost 46 %
  // on a fold.
  void choose_pair(const Candidate& part, const BaseFigures& nominal_figures) {
    rep_.pairs = try_effects(part.fit, figures_of(part.fit), part.fit.effects);
    rep_.pairs_beside = part.effect;
    for (Candidate& second : rep_.pairs) {
      judge(rep_.nominal, nominal_figures, second);
      if (second.cv_improvement < -0.02) {
        char lost[48];
        std::snprintf(lost, sizeof lost, "%.1f", -100.0 * second.cv_improvement);
        second.loses_as_pair =
            "as a pair beside " + part.effect + ", loses " + lost + " % on a left-out block";
      }
    }
    if (const Candidate* second = choose(rep_.pairs)) {
      rep_.chosen.push_back(part);
      rep_.chosen.back().delta_bic = second->delta_bic;  // they earn together
      rep_.chosen.push_back(*second);
      rep_.final_fit = second->fit;
      order_prony_terms(rep_.final_fit.effects, rep_.final_fit.effect_sd);
    }
  }

  // What is left is unexplained when it is well above the measurement noise, structured (not
  // white), and a real share of the output's size in the held-out part: half a percent of its
  // RMS (below that it is a numerical detail of the model, not physics to act on). Its size,
  // not its spread: a stop in the held-out part must not hide a residual. It is compared with
  // the noise, the input's noise through the model, and how far the parameters' own
  // uncertainty moves the held-out prediction. With a named disturbance, what is left is its
  // one-step innovations, against the spread the process itself gives them.
  bool beyond(bool with_parameters) const {
    const DisturbanceFit* d = rep_.disturbance ? &*rep_.disturbance : nullptr;
    const double left = d ? d->rms_held_out : rep_.final_fit.rms_held_out;
    const double spread = with_parameters ? rep_.final_fit.held_out_prediction_sd : 0.0;
    const double floor = std::hypot(
        std::hypot(std::max(rep_.noise_rms, d ? d->predicted_held_out : 0.0), rep_.input_noise_rms),
        spread);
    const double whiteness = d ? d->whiteness_violations : rep_.location.whiteness_violations;
    double mean_square = 0;
    const std::size_t n = y_.size() - end_;
    for (std::size_t k = end_; k < y_.size(); ++k)
      mean_square += y_[k] * y_[k] / static_cast<double>(n);
    return left > 3.0 * std::max(floor, 1e-12) && whiteness > 0.5 &&
           left > o_.min_unexplained_share * std::sqrt(mean_square);
  }

  // Whether the residual is unexplained; where only the parameters' spread covers it, the
  // parameter the calibration part leaves undetermined (the draft's relaxation at rest, in a
  // recording whose only stop is in the held-out part) is said instead, and the nominal's
  // degenerate parameters.
  void judge_residual() {
    rep_.unexplained = beyond(true);
    rep_.undetermined.clear();
    if (!rep_.unexplained && beyond(false) && rep_.final_fit.least_determined >= 0) {
      const FittedValue v = fitted_values(
          ch_, rep_.final_fit)[static_cast<std::size_t>(rep_.final_fit.least_determined)];
      char buf[240];
      std::snprintf(buf, sizeof buf,
                    "%s = %.4g +- %.2g %s (the held-out prediction's SD from the parameters' "
                    "uncertainty, %g, covers the held-out residual)",
                    v.name.c_str(), v.value, v.sd, v.unit.c_str(),
                    rep_.final_fit.held_out_prediction_sd);
      rep_.undetermined = buf;
    }
    rep_.degenerate = degenerate_nominal(ch_, rep_.final_fit);
  }

  // The noise re-estimated under the final model (what it now explains is not noise), then
  // what is left: a parameter that changed once, sought where the residual is unexplained and
  // where the parameters' spread covers it (a clamp law made degenerate by a stiffness that
  // changed mid-run covers a residual 12 times the noise); then, where the recording lacks its
  // column and nothing changed, a field log's unmeasured disturbance (terrain, slip, the stems
  // in the nip) named as a process along the row, the effects judged beside it. Not beside a
  // change: a step in a parameter is no stationary process, and was sought first.
  void judge_what_is_left() {
    rep_.noise_rms = noise_under(rep_.final_fit.prediction);
    rep_.input_noise_rms = ch_.input_noise_rms(r_, rep_.final_fit.nominal, end_);
    judge_residual();
    if (rep_.unexplained || !rep_.undetermined.empty() || !rep_.degenerate.empty()) {
      step("a change of a parameter");
      seek_change();
    }
    if (rep_.change) return;
    step("a disturbance along the row");
    name_disturbance(rep_, r_, split_, o_);
    if (!rep_.disturbance) return;
    rep_.noise_rms = noise_under(rep_.final_fit.prediction);
    rep_.input_noise_rms = ch_.input_noise_rms(r_, rep_.final_fit.nominal, end_);
    judge_residual();
  }

  // A change earns its place by the same rules as an effect; the final fit then holds the
  // values after it.
  void seek_change() {
    std::optional<ChangePoint> cp =
        find_change_point(ch_, r_, split_, rep_.final_fit, rep_.noise_rms);
    if (!cp) return;
    const double noise2 = rep_.noise_rms * rep_.noise_rms;
    const double before2 = rep_.final_fit.rms_calibration * rep_.final_fit.rms_calibration;
    const double after2 = cp->rms_calibration * cp->rms_calibration;
    const double explained = before2 > noise2 ? (before2 - after2) / (before2 - noise2) : 0.0;
    const double held_out_gain = rep_.final_fit.rms_held_out > 0
                                     ? 1.0 - cp->rms_held_out / rep_.final_fit.rms_held_out
                                     : 0.0;
    if (cp->delta_bic >= -o_.min_delta_bic || explained < o_.min_explained ||
        held_out_gain < o_.min_improvement || cp->changed.empty())
      return;
    rep_.final_fit.nominal = cp->after.nominal;
    rep_.final_fit.nominal_sd = cp->after.nominal_sd;
    rep_.final_fit.effects = cp->after.effects;
    rep_.final_fit.effect_sd = cp->after.effect_sd;
    rep_.final_fit.prediction = cp->prediction;
    rep_.final_fit.rms_calibration = cp->rms_calibration;
    rep_.final_fit.rms_held_out = cp->rms_held_out;
    rep_.change = std::move(cp);
    rep_.noise_rms =
        std::min(rep_.noise_rms, white_noise_rms(residual_of(rep_.final_fit.prediction, y_), end_));
    judge_residual();
  }

  // A value that ended at an edge of its range (at_range_edge).
  void at_edge(const ParamSpec& p, double v, const std::string& owner, const char* structure) {
    if (!at_range_edge(p, v)) return;
    char buf[300];
    std::snprintf(buf, sizeof buf, "%s%s = %.4g %s (range %.4g to %.4g): %s may be wrong here",
                  owner.c_str(), p.name.c_str(), v, p.unit.c_str(), p.lower, p.upper, structure);
    rep_.at_range_edge.emplace_back(buf);
  }

  // The nominal's values, and each named effect's (its bounds as the fit had them, scaled to
  // the output where they are).
  void mark_range_edges() {
    const std::vector<ParamSpec> specs = ch_.nominal_params();
    for (std::size_t i = 0; i < specs.size() && i < rep_.final_fit.nominal.size(); ++i)
      if (!specs[i].grid) at_edge(specs[i], rep_.final_fit.nominal[i], "", "the nominal structure");
    for (const Effect& named : rep_.final_fit.effects) {
      std::vector<ParamSpec> bounds = named.spec->params;
      bounds_for_output(bounds, y_);
      for (std::size_t k = 0; k < bounds.size() && k < named.values.size(); ++k)
        at_edge(bounds[k], named.values[k], named.spec->name + ": ", "the effect's form");
    }
  }

  void set_verdict() {
    const char* still = "; a residual is still unexplained";
    if (!rep_.chosen.empty() || rep_.change)
      rep_.verdict = std::string("effect(s) found") + (rep_.unexplained ? still : "");
    else if (rep_.disturbance)
      rep_.verdict = std::string("disturbance named") + (rep_.unexplained ? still : "");
    else
      rep_.verdict = rep_.unexplained ? "unexplained residual" : "no significant mismatch";
  }

  const ChannelModel& ch_;
  const Recording& r_;
  const FitOptions& o_;
  const Split& split_;
  const std::vector<double>& y_;
  const std::size_t end_;
  ChannelReport rep_;
  std::vector<Effect> known_;
  std::vector<double> data_guess_;
  BaseFigures nominal_figures_;
};

}  // namespace

std::string bic_shortfall(double delta_bic, double min_delta_bic) {
  char buf[120];
  if (delta_bic > 0.0)
    std::snprintf(buf, sizeof buf, "raises BIC by %.1f; it must lower it by %.0f", delta_bic,
                  min_delta_bic);
  else
    std::snprintf(buf, sizeof buf, "lowers BIC by %.1f; %.0f is required", -delta_bic,
                  min_delta_bic);
  return buf;
}

std::string rejection(const Candidate& c, const FitOptions& o) {
  if (!c.not_separable.empty()) return c.not_separable;
  if (!c.loses_as_pair.empty()) return c.loses_as_pair;
  if (std::string why = unresolved_size(c); !why.empty()) return why;
  char buf[200];
  if (c.delta_bic >= -o.min_delta_bic) return bic_shortfall(c.delta_bic, o.min_delta_bic);
  if (c.explained < o.min_explained) {
    std::snprintf(buf, sizeof buf,
                  "explains %.0f %% of the residual beyond noise; %.0f %% is required",
                  100.0 * c.explained, 100.0 * o.min_explained);
    return buf;
  }
  if (c.credited_rms > 0.0 && c.own_rms < 0.5 * c.credited_rms) {
    std::snprintf(buf, sizeof buf,
                  "its own part of the fit, %.3g RMS, is under half of what it is credited with "
                  "(%.3g): the nominal refitted beside it took the rest",
                  c.own_rms, c.credited_rms);
    return buf;
  }
  if (c.cv_improvement < o.min_improvement && c.held_out_improvement < o.min_improvement) {
    std::snprintf(buf, sizeof buf,
                  "improves the best fold by %.1f %% and the held-out part by %.1f %%; %.0f %% "
                  "is required of one",
                  100.0 * c.cv_improvement, 100.0 * c.held_out_improvement,
                  100.0 * o.min_improvement);
    return buf;
  }
  // The model with it must beat the nominal on the held-out part (issue 52), not tie it within
  // a share: a vibration of 0.7 um on the depth, under its noise, once passed at -0.5 %.
  if (c.held_out_improvement < 0.0) {
    std::snprintf(buf, sizeof buf, "worsens the held-out part by %.1f %%",
                  -100.0 * c.held_out_improvement);
    return buf;
  }
  return "";
}

ChannelReport analyse_channel(const ChannelModel& ch, const Recording& r, const FitOptions& o,
                              const Split& split) {
  return ChannelAnalysis(ch, r, o, split).run();
}

}  // namespace planter::analysis
