#include "analysis/fit_outputs.h"

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/effect_hooks.h"
#include "analysis/model_file.h"
#include "config/output_set.h"
#include "firmware/io/signal_table.h"
#include "report/chart.h"
#include "report/html_text.h"

namespace planter::analysis {
namespace {

// A column's unit, from the signal table; "" for a column it does not declare.
std::string column_unit(const std::string& column) {
  const SignalDecl* s = find_signal(column);
  return s != nullptr ? std::string(s->unit) : std::string();
}

// An effect's parameters are in the units of the channel they act on: "output units/s" on the
// clamp-force channel is N/s.
std::string concrete_unit(std::string unit, const ChannelModel& c) {
  for (const auto& [generic, column] :
       {std::pair<std::string, std::string>{"output units", c.output()},
        {"input units", c.input()}}) {
    const std::string u = column_unit(column);
    const std::size_t at = unit.find(generic);
    if (at != std::string::npos && !u.empty()) unit.replace(at, generic.size(), u);
  }
  return unit;
}

nlohmann::json params_json(const std::vector<ParamSpec>& specs, const std::vector<double>& v,
                           const std::vector<double>& sd, const ChannelModel& c) {
  nlohmann::json j = nlohmann::json::array();
  for (std::size_t k = 0; k < specs.size() && k < v.size(); ++k) {
    j.push_back({{"name", specs[k].name},
                 {"value", v[k]},
                 {"sd", k < sd.size() ? sd[k] : 0.0},
                 {"unit", concrete_unit(specs[k].unit, c)},
                 {"grid", specs[k].grid}});
  }
  return j;
}

// An effect that is another effect seen from this channel says whose (`hold_of`: a friction's
// own hold at rest; `through_speed_loop_of`: the disc's friction through the speed loop), as
// "output:effect", and why (`explained`).
nlohmann::json effects_json(const ChannelReport& report) {
  const ChannelFit& f = report.final_fit;
  nlohmann::json j = nlohmann::json::array();
  for (std::size_t e = 0; e < f.effects.size(); ++e) {
    nlohmann::json entry = {
        {"effect", f.effects[e].spec->name},
        {"signature", f.effects[e].spec->signature},
        {"parameters", params_json(f.effects[e].spec->params, f.effects[e].values,
                                   e < f.effect_sd.size() ? f.effect_sd[e] : std::vector<double>{},
                                   *report.channel)}};
    if (const auto* x = report.explained_by(e)) {
      const bool hold = x->relation == ChannelReport::ExplainedBy::Relation::kHoldAtRest;
      entry[hold ? "hold_of" : "through_speed_loop_of"] = x->by;
      entry["explained"] = x->note;
    }
    j.push_back(entry);
  }
  return j;
}

// A tone found at the recording's rate, as an effect entry (the periodic effect's parameters).
nlohmann::json fast_tone_json(const FastTone& f, const ChannelModel& c, double above_hz) {
  const EffectSpec& spec = effect_spec(EffectKind::kPeriodic);
  return {{"effect", spec.name},
          {"signature", spec.signature},
          {"parameters",
           params_json(spec.params, {f.tone.amplitude, f.tone.frequency_hz, f.tone.phase_rad},
                       {f.amplitude_sd, f.frequency_sd_hz, f.phase_sd_rad}, c)},
          {"found_at",
           "the recording's own rate, above the analysed " + std::to_string(above_hz) + " Hz"},
          {"order", f.order},
          {"fundamental_hz", f.fundamental_hz},
          {"held_out_rms", {{"before", f.held_out_rms_before}, {"after", f.held_out_rms_after}}}};
}

nlohmann::json disturbance_json(const DisturbanceFit& d) {
  const double k = d.spec->shown_per_unit;
  return {{"name", d.spec->name},
          {"unit", d.spec->unit},
          {"rms", k * d.rms},
          {"rms_sd", k * d.rms_sd},
          {d.periodic ? "wavelength_m" : "correlation_length_m", d.scale_m},
          {"scale_sd_m", d.scale_sd_m},
          {"damping", d.zeta},
          {"mean", k * d.mean},
          {"noise_rms", d.noise_rms},
          {"delta_bic", d.delta_bic},
          {"held_out_one_step_rms", d.rms_held_out},
          {"held_out_one_step_rms_predicted", d.predicted_held_out},
          {"whiteness_violations", d.whiteness_violations}};
}

}  // namespace

std::string not_exercised(const ChannelReport& c) {
  std::string out;
  const std::vector<ParamSpec> specs = c.channel->nominal_params();
  for (std::size_t k = 0; k < c.final_fit.nominal_exercised.size() && k < specs.size(); ++k) {
    if (c.final_fit.nominal_exercised[k]) continue;
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s%s (at %.4g %s)", out.empty() ? "" : ", ",
                  specs[k].name.c_str(), c.final_fit.nominal[k],
                  concrete_unit(specs[k].unit, *c.channel).c_str());
    out += buf;
  }
  return out;
}

double held_out_after(const ChannelReport& c) {
  return c.disturbance ? c.disturbance->rms_held_out : c.final_fit.rms_held_out;
}

// "relaxation of the clamp: fraction = 0.2987 +- 0.001, tau = 3.023 +- 0.011 s"
// An effect that is another effect seen from this channel says so after its values.
std::string effect_text(const ChannelReport& report, std::size_t e) {
  const ChannelFit& f = report.final_fit;
  const ChannelModel& c = *report.channel;
  const Effect& eff = f.effects[e];
  std::string out = eff.spec->name + ":";
  for (std::size_t k = 0; k < eff.values.size() && k < eff.spec->params.size(); ++k) {
    const double sd = f.effect_sd_of(e, k);
    char buf[96];
    std::snprintf(buf, sizeof buf, " %.4g +- %.2g", eff.values[k], sd);
    const std::string unit = concrete_unit(eff.spec->params[k].unit, c);
    out += (k ? ", " : " ") + eff.spec->params[k].name + " =" + buf +
           (unit.empty() || unit == "-" || unit == "1" ? "" : " " + unit);
  }
  if (const auto* x = report.explained_by(e)) out += " (" + x->note + ")";
  return out;
}

namespace {

// A parameter that changed once: when, and each value before and after.
nlohmann::json change_json(const ChangePoint& change, const ChannelModel& channel) {
  nlohmann::json moved = nlohmann::json::array();
  for (const auto& m : change.changed)
    moved.push_back({{"name", m.name},
                     {"unit", concrete_unit(m.unit, channel)},
                     {"before", m.before},
                     {"before_sd", m.before_sd},
                     {"after", m.after},
                     {"after_sd", m.after_sd}});
  return {{"at_s", change.at_s},
          {"at_sd_s", change.at_sd_s},
          {"delta_bic", change.delta_bic},
          {"tied", change.tied},
          {"parameters", moved}};
}

// A long recording's model tracked window by window: each parameter's verdict and values.
nlohmann::json day_json(const ChannelDay& d, const ChannelModel& channel) {
  nlohmann::json tracks = nlohmann::json::array();
  for (const Track& t : d.tracks) {
    nlohmann::json tj{{"name", t.name},       {"unit", concrete_unit(t.unit, channel)},
                      {"verdict", t.verdict}, {"t_s", t.t_s},
                      {"value", t.value},     {"sd", t.sd}};
    if (t.verdict == "drifting") tj["slope_per_h"] = t.slope_per_h;
    if (t.verdict == "changed") {
      tj["at_s"] = t.at_s;
      tj["at_sd_s"] = t.at_sd_s;
      tj["before"] = t.before;
      tj["after"] = t.after;
    }
    tracks.push_back(tj);
  }
  return {{"verdict", d.verdict}, {"tracks", tracks}};
}

// The ties, and each candidate tried with its figures (and the pairs beside a first effect).
void candidates_json(const ChannelReport& c, nlohmann::json& ch) {
  ch["ties"] = nlohmann::json::array();
  for (const auto& tie : c.ties)
    ch["ties"].push_back({{"chosen", tie.chosen},
                          {"alternative", tie.alternative},
                          {"delta_bic", tie.delta_bic},
                          {"experiment", tie.experiment}});
  auto figures = [](const Candidate& cand) {
    return nlohmann::json{{"effect", cand.effect},
                          {"delta_bic", cand.delta_bic},
                          {"held_out_improvement", cand.held_out_improvement},
                          {"cv_improvement", cand.cv_improvement},
                          {"explained", cand.explained}};
  };
  for (const auto& cand : c.ranked) ch["ranked"].push_back(figures(cand));
  // Second effects tried beside a first that explained only part (each judged, with it,
  // against the nominal).
  if (!c.pairs.empty()) {
    ch["pairs_beside"] = c.pairs_beside;
    for (const auto& cand : c.pairs) ch["pairs"].push_back(figures(cand));
  }
}

nlohmann::json location_json(const Location& l) {
  nlohmann::json loc{{"whiteness_violations", l.whiteness_violations},
                     {"input_correlation", l.input_correlation},
                     {"worst_window_start_s", l.worst_window_start_s},
                     {"worst_window_ratio", l.worst_window_ratio},
                     {"time_correlation", l.time_correlation},
                     {"dominant_frequency_hz", l.dominant_frequency_hz},
                     {"dominant_amplitude", l.dominant_amplitude}};
  for (const auto& g : l.regimes)
    loc["regimes"].push_back({{"regime", g.name}, {"rms_ratio", g.rms_ratio}, {"share", g.share}});
  return loc;
}

nlohmann::json channel_json(const FitReport& r, const ChannelReport& c) {
  nlohmann::json ch;
  ch["subsystem"] = c.channel->subsystem();
  ch["output"] = c.channel->output();
  ch["output_unit"] = column_unit(c.channel->output());
  ch["verdict"] = c.verdict;
  if (!c.refined.empty()) ch["refined_at_full_rate"] = c.refined;
  ch["at_range_edge"] = c.at_range_edge;
  ch["nominal"] =
      params_json(c.channel->nominal_params(), c.nominal.nominal, c.nominal.nominal_sd, *c.channel);
  ch["noise_rms"] = c.noise_rms;
  ch["resolution_rms"] = c.resolution_rms;
  if (c.logged_step > 0.0) ch["recorded_in_steps_of"] = c.logged_step;
  ch["input_noise_rms"] = c.input_noise_rms;
  ch["held_out_prediction_sd"] = c.final_fit.held_out_prediction_sd;
  if (!c.undetermined.empty()) ch["undetermined"] = c.undetermined;
  if (!c.degenerate.empty()) ch["degenerate"] = c.degenerate;
  if (c.disturbance) ch["disturbance"] = disturbance_json(*c.disturbance);
  if (!c.beside_disturbance.empty()) ch["beside_disturbance"] = c.beside_disturbance;
  ch["held_out_rms"] = {{"nominal", c.nominal.rms_held_out},
                        {"augmented", c.final_fit.rms_held_out},
                        {"one_step_ahead", held_out_after(c)}};
  if (c.one_step_nominal > 0.0) ch["held_out_rms"]["one_step_ahead_nominal"] = c.one_step_nominal;
  ch["calibration_rms"] = {{"nominal", c.nominal.rms_calibration},
                           {"augmented", c.final_fit.rms_calibration}};
  ch["effects"] = effects_json(c);
  for (const auto& f : c.fast_tones)
    ch["effects"].push_back(fast_tone_json(f, *c.channel, r.analysed_up_to_hz));
  ch["augmented_nominal"] = params_json(c.channel->nominal_params(), c.final_fit.nominal,
                                        c.final_fit.nominal_sd, *c.channel);
  // A parameter the rows never exercised is not fitted: no SD, and said (issue 52).
  for (std::size_t k = 0; k < c.final_fit.nominal_exercised.size(); ++k) {
    if (c.final_fit.nominal_exercised[k] || k >= ch["augmented_nominal"].size()) continue;
    ch["augmented_nominal"][k]["exercised"] = false;
    ch["augmented_nominal"][k].erase("sd");
  }
  if (c.change) ch["change"] = change_json(*c.change, *c.channel);
  if (r.day)
    ch["across_the_recording"] =
        day_json(r.day->channels[static_cast<std::size_t>(&c - r.channels.data())], *c.channel);
  candidates_json(c, ch);
  ch["location"] = location_json(c.location);
  return ch;
}

}  // namespace

std::string fit_json(const FitReport& r, double wall_s) {
  nlohmann::json j;
  j["recording"] = r.file;
  j["rows"] = r.rows;
  j["duration_s"] = r.duration_s;
  j["held_out_from_s"] = r.held_out_from_s;
  j["rate_hz"] = r.rate_hz;
  if (r.day)
    j["windows"] = {{"count", r.day->windows},
                    {"window_s", r.day->window_s},
                    {"rows", r.day->rows},
                    {"untracked_rows", r.day->untracked_rows},
                    {"duration_s", r.day->duration_s}};
  j["analysed_rows"] = r.analysed_rows;
  j["analysed_up_to_hz"] = r.analysed_up_to_hz;
  j["wall_s"] = wall_s;
  j["unobservable"] = r.unobservable;
  j["known_inputs"] = r.known_inputs;
  if (!r.stopped_state.empty())
    j["left_out_after"] = {
        {"state", r.stopped_state}, {"t_s", r.stopped_at_s}, {"rows", r.stopped_rows}};
  j["glitches"] = nlohmann::json::array();
  for (const auto& g : r.glitches)
    j["glitches"].push_back(
        {{"column", g.column}, {"t_s", g.t_s}, {"value", g.value}, {"replaced_by", g.replaced_by}});
  bool any = false, unexplained = false;
  for (const auto& c : r.channels) {
    any = any || !c.chosen.empty() || !c.fast_tones.empty();
    unexplained = unexplained || c.unexplained;
    j["channels"].push_back(channel_json(r, c));
  }
  j["verdict"] =
      any ? (unexplained ? "effects found; unexplained residual remains" : "effects found")
          : (unexplained ? "unexplained residual" : "no significant mismatch");
  return j.dump(2) + "\n";
}

std::string fit_model_toml(const FitReport& r) {
  std::ostringstream s;
  s.precision(17);  // round trip: replay predicts what the fit predicted
  s << "# The augmented model planter-fit found (nominal structures of docs/recording-format.md "
       "plus the\n"
       "# effects that earned their parameters). Run it: planter-sim replay MODEL RECORDING\n";
  for (const auto& c : r.channels) {
    s << "\n[[channel]]\noutput = \"" << c.channel->output() << "\"\nsubsystem = \""
      << c.channel->subsystem() << "\"\n";
    const auto specs = c.channel->nominal_params();
    for (std::size_t k = 0; k < specs.size(); ++k)
      s << model_key(specs[k].name) << " = " << c.final_fit.nominal[k] << "\n";
    if (c.change)
      s << "# changed at t = " << c.change->at_s
        << " s: the values below are those after the change (fit.json has both sides)\n";
    std::vector<Effect> effects = c.final_fit.effects;
    // The strongest tone found above the analysed rate, when the fit has no periodic effect of
    // its own (a channel takes one of each).
    if (!c.fast_tones.empty() && find_effect(effects, EffectKind::kPeriodic) == nullptr) {
      const Tone& tone = c.fast_tones.front().tone;
      effects.push_back({&effect_spec(EffectKind::kPeriodic),
                         {tone.amplitude, tone.frequency_hz, tone.phase_rad}});
    }
    for (const auto& e : effects) {
      s << "\n[[channel.effect]]\nname = \"" << e.spec->name << "\"\n";
      for (std::size_t k = 0; k < e.values.size(); ++k)
        s << model_key(e.spec->params[k].name) << " = " << e.values[k] << "\n";
    }
  }
  return s.str();
}

namespace {

// The page's head and what the recording held: rows, what was left out and why.
void report_preamble(std::ostream& h, const FitReport& r) {
  h << "<!doctype html><html><head>" << report::kReportHead
    << "<title>planter-fit</title><style>"
       "body{font-family:sans-serif;max-width:900px;margin:20px auto}td,th{padding:2px 8px}"
       "table{border-collapse:collapse}tr:nth-child(even){background:#f4f4f4}</style>"
    << report::ChartPage::head() << "</head><body><h1>planter-fit: " << report::html_path(r.file)
    << "</h1><p>" << r.rows << " rows, " << r.duration_s
    << " s; the last 30 % is held out for the verdict.</p>";
  if (!r.unobservable.empty()) {
    h << "<p>Not observable (columns missing or constant):";
    for (const auto& u : r.unobservable) h << " " << u << ";";
    h << "</p>";
  }
  if (!r.stopped_state.empty())
    h << "<p>The machine entered '" << report::html_escape(r.stopped_state) << "' at "
      << r.stopped_at_s << " s: the " << r.stopped_rows
      << " rows from there on are left out (its drives are disabled and a silent node's values "
         "stale).</p>";
  if (!r.known_inputs.empty()) {
    h << "<p>Known disturbances the recording carries, taken as inputs:";
    for (const auto& k : r.known_inputs) h << " " << report::html_escape(k) << ";";
    h << "</p>";
  }
  if (!r.glitches.empty()) {
    h << "<p>Excluded " << r.glitches.size()
      << " single-sample glitch(es), replaced by their neighbours' mean:";
    for (const auto& g : r.glitches)
      h << " " << report::html_escape(g.column) << " = " << g.value << " at " << g.t_s << " s;";
    h << "</p>";
  }
}

// The verdicts first: per channel, what was found and how much better the held-out part got;
// then the rules a candidate is held to.
void summary_table(std::ostream& h, const FitReport& r) {
  h << "<h2>Summary</h2><table><tr><th>channel</th><th>verdict</th><th>held-out RMS error: "
       "nominal &rarr; with the effects</th></tr>";
  for (const auto& c : r.channels) {
    const std::string unit = column_unit(c.channel->output());
    const bool found = !c.final_fit.effects.empty() || c.change;
    h << "<tr><td>" << c.channel->subsystem() << ": " << c.channel->output() << "</td><td"
      << (found ? " style='color:#a40'" : "") << "><b>" << report::html_escape(c.verdict) << "</b>";
    for (std::size_t e = 0; e < c.final_fit.effects.size(); ++e)
      h << "<br>" << report::html_escape(effect_text(c, e));
    if (c.disturbance) h << "<br>" << report::html_escape(c.disturbance->describe());
    h << "</td><td>" << c.nominal.rms_held_out << " &rarr; " << held_out_after(c) << " "
      << report::html_escape(unit) << (c.disturbance ? " (one step ahead)" : "") << "</td></tr>";
  }
  h << "</table><p>A candidate effect is kept when it lowers BIC by more than "
    << r.options.min_delta_bic << ", explains at least " << 100.0 * r.options.min_explained
    << " % of the residual beyond the measurement noise, improves a cross-validation fold or the "
       "held-out part by "
    << 100.0 * r.options.min_improvement
    << " %, and does not worsen the held-out part. Of the candidates kept, the one with the "
       "lowest held-out RMS is named; those within "
    << 100.0 * r.options.held_out_tie
    << " % of it tie on that, and the lowest BIC among them is named. Each channel's table "
       "below says which criterion each other candidate failed.</p>";
}

// What the channel names and says beside its verdict: effects, a process, notes, a change,
// fast tones, ties.
void channel_notes(std::ostream& h, const FitReport& r, const ChannelReport& c) {
  for (std::size_t e = 0; e < c.final_fit.effects.size(); ++e)
    h << "<p><b>" << report::html_escape(effect_text(c, e)) << "</b> ("
      << c.final_fit.effects[e].spec->signature << ")</p>";
  if (c.disturbance)
    h << "<p><b>" << report::html_escape(c.disturbance->describe())
      << "</b> (an unmeasured process along the row, fitted from the residual: its one-step "
         "predictions leave a held-out RMS of "
      << c.disturbance->rms_held_out << ", where the process gives "
      << c.disturbance->predicted_held_out << ")</p>";
  for (const std::string& note : c.beside_disturbance)
    h << "<p>" << report::html_escape(note) << "</p>";
  if (!c.degenerate.empty()) h << "<p><b>" << report::html_escape(c.degenerate) << "</b></p>";
  if (const std::string idle = not_exercised(c); !idle.empty())
    h << "<p>Not exercised by this recording, so not fitted: " << report::html_escape(idle)
      << ".</p>";
  if (c.logged_step > 0.0)
    h << "<p>" << c.channel->output() << " is recorded in steps of " << c.logged_step
      << ": their rounding, " << c.resolution_rms
      << " RMS, is the floor no model matches closer than.</p>";
  if (r.day) {
    const ChannelDay& d = r.day->channels[static_cast<std::size_t>(&c - r.channels.data())];
    h << "<p><b>Across " << r.day->windows << " windows of " << r.day->window_s
      << " s: " << report::html_escape(d.verdict) << "</b></p><table><tr><th>parameter</th>"
      << "<th>verdict</th><th>first window</th><th>last window</th></tr>";
    for (const Track& track : d.tracks)
      if (!track.value.empty())
        h << "<tr><td>" << track.name << "</td><td>" << track.verdict << "</td><td>"
          << track.value.front() << "</td><td>" << track.value.back() << "</td></tr>";
    h << "</table>";
  }
  if (c.change) {
    h << "<p><b>a parameter changed at t = " << c.change->at_s << " &plusmn; " << c.change->at_sd_s
      << " s</b>:";
    for (const auto& m : c.change->changed)
      h << (&m == &c.change->changed.front() ? " "
            : c.change->tied                 ? ", or "
                                             : ", ")
        << m.name << " " << m.before << " &rarr; " << m.after << " "
        << report::html_escape(concrete_unit(m.unit, *c.channel));
    if (c.change->tied)
      h << " (this recording cannot tell which: a sweep of " << c.channel->input()
        << " over its range would)";
    h << ".</p>";
  }
  for (const auto& f : c.fast_tones)
    h << "<p><b>periodic disturbance (vibration) above the analysed " << r.analysed_up_to_hz
      << " Hz</b>, found at the recording's own rate: " << f.tone.frequency_hz << " Hz"
      << (f.order > 1 ? " (order " + std::to_string(f.order) + " of " +
                            std::to_string(f.fundamental_hz) + " Hz)"
                      : std::string())
      << ", amplitude " << f.tone.amplitude << "; held-out RMS " << f.held_out_rms_before
      << " &rarr; " << f.held_out_rms_after << ".</p>";
  for (const auto& tie : c.ties)
    h << "<p><b>" << tie.chosen << " or " << tie.alternative
      << "</b>: this recording cannot separate them (&Delta;BIC " << tie.delta_bic
      << "). To tell them apart, record " << report::html_escape(tie.experiment) << ".</p>";
}

// Each candidate tried, with the criterion it failed.
void candidates_table(std::ostream& h, const FitReport& r, const ChannelReport& c) {
  h << "<table><tr><th>candidate</th><th>&Delta;BIC</th><th>explained</th>"
       "<th>best fold</th><th>held-out</th><th>kept?</th></tr>";
  // A share far below -100 % is a candidate that made the fit much worse: say so, not -4.8e5 %.
  auto share = [](double v) {
    return v < -1.0 ? std::string("worse") : report::fixed(100.0 * v, 1) + " %";
  };
  auto rows = [&](const std::vector<Candidate>& cands, const std::string& beside) {
    for (const auto& cand : cands) {
      bool kept = false;
      for (const auto& e : c.final_fit.effects) kept = kept || e.spec == cand.spec;
      const std::string why = rejection(cand, r.options);
      h << "<tr><td>" << (beside.empty() ? "" : report::html_escape(beside) + " with ")
        << cand.effect << "</td><td>" << report::fixed(cand.delta_bic, 1) << "</td><td>"
        << share(cand.explained) << "</td><td>" << share(cand.cv_improvement) << "</td><td>"
        << share(cand.held_out_improvement) << "</td><td>"
        << (kept          ? "<b>kept</b>"
            : why.empty() ? "earns its place; another explains the same better or is simpler"
                          : "no: " + report::html_escape(why))
        << "</td></tr>";
    }
  };
  rows(c.ranked, "");
  // No effect earned alone, one explained part: the pairs beside it, each against the nominal.
  rows(c.pairs, c.pairs_beside);
  h << "</table>";
}

// Where the nominal residual is: its whiteness, its correlations, its worst window, regimes.
void residual_location(std::ostream& h, const ChannelReport& c) {
  h << "<p>Where the nominal residual is: whiteness violations "
    << 100.0 * c.location.whiteness_violations << " % of lags; input correlation "
    << c.location.input_correlation << "; worst window at " << c.location.worst_window_start_s
    << " s (" << c.location.worst_window_ratio << "x the median); drift correlation "
    << c.location.time_correlation << "; spectrum peak " << c.location.dominant_frequency_hz
    << " Hz.";
  for (const auto& g : c.location.regimes) h << " " << g.name << ": " << g.rms_ratio << "x;";
  h << "</p>";
}

// The recording against the nominal and augmented predictions, and both residuals, on every
// stride-th row.
void channel_charts(std::ostream& h, const FitReport& r, const ChannelReport& c,
                    const Recording& rec, report::ChartPage& charts, const std::vector<double>& t,
                    std::size_t stride) {
  const std::size_t n = rec.size();
  const auto& y = rec.at(c.channel->output());
  std::vector<double> ys, nom, aug, e0, e1;
  for (std::size_t k = 0; k < n; k += stride) {
    ys.push_back(y[k]);
    nom.push_back(c.nominal.prediction[k]);
    aug.push_back(c.final_fit.prediction[k]);
    e0.push_back(c.nominal.prediction[k] - y[k]);
    e1.push_back(c.final_fit.prediction[k] - y[k]);
  }
  const auto [lo, hi] = std::minmax_element(ys.begin(), ys.end());
  double emax = 1e-12;
  for (double v : e0) emax = std::max(emax, std::abs(v));
  // Marks on the time axis: where the held-out part starts, and when a parameter changed.
  std::vector<report::Marker> marks{{r.held_out_from_s, "#999", "held out from here"}};
  if (c.change) marks.push_back({c.change->at_s, "#e80", "changed"});
  const std::string unit = column_unit(c.channel->output());
  h << charts.lines(
           {c.channel->output(), unit, "time [s]", *lo, *hi, marks, {}, ""}, t,
           {{&ys, "#222", "recording"}, {&nom, "#36c", "nominal"}, {&aug, "#c33", "augmented"}})
    << charts.lines(
           {"residual of " + c.channel->output(), unit, "time [s]", -emax, emax, marks, {}, ""}, t,
           {{&e0, "#36c", "nominal"}, {&e1, "#c33", "augmented"}});
}

void channel_section(std::ostream& h, const FitReport& r, const ChannelReport& c,
                     const Recording& rec, report::ChartPage& charts, const std::vector<double>& t,
                     std::size_t stride) {
  h << "<h2>" << c.channel->subsystem() << ": " << c.channel->output() << " &mdash; " << c.verdict
    << "</h2><p>Held-out RMS error: nominal " << c.nominal.rms_held_out << ", augmented <b>"
    << c.final_fit.rms_held_out << "</b>; measurement noise about " << c.noise_rms;
  if (c.input_noise_rms > 0.0)
    h << ", and " << c.input_noise_rms << " from the measured input's noise through the model";
  h << ".</p>";
  channel_notes(h, r, c);
  candidates_table(h, r, c);
  residual_location(h, c);
  channel_charts(h, r, c, rec, charts, t, stride);
}

}  // namespace

std::string fit_report_html(const FitReport& r, const Recording& rec) {
  std::ostringstream h;
  h.precision(4);
  report::ChartPage charts;
  report_preamble(h, r);
  summary_table(h, r);
  const std::size_t n = rec.size();
  const std::size_t stride = std::max<std::size_t>(1, n / 3000);
  std::vector<double> t;
  for (std::size_t k = 0; k < n; k += stride) t.push_back(rec.t[k]);
  for (const auto& c : r.channels) channel_section(h, r, c, rec, charts, t, stride);
  h << "</body></html>\n";
  return h.str();
}

std::string write_fit_outputs(config::OutputSet& out, const FitReport& r, const Recording& rec,
                              double wall_s) {
  const std::string json = fit_json(r, wall_s);
  out.write("fit.json", json);
  out.write("model.toml", fit_model_toml(r));
  out.write("report.html", fit_report_html(r, rec));
  out.commit();
  return json;
}

}  // namespace planter::analysis
