#include "analysis/mismatch.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>

#include "analysis/at_rest.h"
#include "analysis/channel_analysis.h"
#include "analysis/decimation.h"
#include "analysis/effect_hooks.h"
#include "analysis/model_file.h"
#include "analysis/residual_stats.h"
#include "firmware/io/signal_table.h"
#include "firmware/supervisor/supervisor.h"

namespace planter::analysis {

std::vector<std::string> channel_columns() {
  std::vector<std::string> read;
  for (const ChannelModel* ch : all_channels()) {
    for (const std::string& c : ch->needs())
      if (std::find(read.begin(), read.end(), c) == read.end()) read.push_back(c);
    for (const std::string& c : ch->known_inputs())
      if (std::find(read.begin(), read.end(), c) == read.end()) read.push_back(c);
  }
  return read;
}

// The columns a glitch is looked for in: the sensors'. Not what the controller computed and
// acted on (a command; the ground speed it estimated from the recorded wheel edges, whose
// dips as the edges thin out at a stop are real and modelled), nor the disturbances the
// simulator declares (its own truth).
std::vector<std::string> glitch_columns(const Recording& r) {
  std::vector<std::string> out;
  for (const std::string& c : channel_columns()) {
    const bool command = c.find("_cmd") != std::string::npos;
    const bool declared = c.starts_with("known_");
    const bool estimated = c == "v_wheel" && r.has("wheel_counts");
    if (!command && !declared && !estimated) out.push_back(c);
  }
  return out;
}

Recording analysed_recording(const Recording& full, const FitOptions& o,
                             const std::vector<Glitch>& glitches) {
  // At most max_rows rows: the fits simulate the whole record for each evaluation. The
  // columns the channels read are low-pass filtered first, so a fast vibration is removed
  // rather than aliased (it is looked for at the recording's own rate: fast_tones.h).
  const std::size_t stride = (full.size() + o.max_rows - 1) / o.max_rows;
  const Recording& clean = glitches.empty() ? full : without_glitches(full, glitches);
  std::vector<std::string> travel;
  for (const ChannelModel* ch : all_channels())
    if (!ch->displacement().empty()) travel.push_back(ch->displacement());
  Recording out = decimated(clean, stride, channel_columns(), travel);
  if (!clean.has("v_wheel")) return out;
  // The standstills at the full rate, kept row by row: the filter leaves no exact zero in the
  // wheel's speed. Carried at the full rate too: the fits simulate only up to the calibration
  // part's end (channel_fit.cpp), and the standstill test looks half a second ahead.
  const std::vector<bool> rest = wheel_at_rest(clean);
  std::vector<double>& column = out.signals[kAtRestColumn];
  for (std::size_t k = 0; k < rest.size(); k += stride) column.push_back(rest[k] ? 1.0 : 0.0);
  return out;
}

// The first row where the supervisor faulted or the e-stop was pressed (the recording's size if
// none): from there the drives are disabled and a silent node's values are stale, which no
// nominal structure describes (a fault is the supervisor's to report, not a missing effect).
std::size_t first_stopped_row(const Recording& r) {
  const std::string fault = supervisor_state_name(SupervisorState::kFault);
  const std::string estop = supervisor_state_name(SupervisorState::kEStop);
  for (std::size_t k = 0; k < r.state.size(); ++k)
    if (r.state[k] == fault || r.state[k] == estop) return k;
  return r.size();
}

// Effects `out` (indices into the final fit's) are left out of what the channel names; the
// other values were fitted with them, so the fit without them starts again from the nominal
// one on the analysed rows, with whatever else was chosen.
void leave_out(std::vector<std::size_t> out, ChannelReport& c, const Recording& analysed,
               std::size_t analysed_held_out) {
  auto& fx = c.final_fit.effects;
  std::sort(out.rbegin(), out.rend());
  for (std::size_t index : out) {
    const std::string name = fx[index].spec->name;
    if (index < c.final_fit.effect_sd.size())
      c.final_fit.effect_sd.erase(c.final_fit.effect_sd.begin() +
                                  static_cast<std::ptrdiff_t>(index));
    fx.erase(fx.begin() + static_cast<std::ptrdiff_t>(index));
    c.chosen.erase(std::remove_if(c.chosen.begin(), c.chosen.end(),
                                  [&](const Candidate& k) { return k.effect == name; }),
                   c.chosen.end());
  }
  if (fx.empty()) {
    c.final_fit = c.nominal;
  } else {
    Split analysed_split;
    analysed_split.calibration_end = analysed_held_out;
    c.final_fit = fit_channel(*c.channel, analysed, analysed_split, c.nominal.nominal, fx);
  }
  if (c.chosen.empty())
    c.verdict = c.unexplained ? "unexplained residual" : "no significant mismatch";
}

// A transport delay found on decimated rows is a time-resolution parameter: the decimation's
// own timing (a command averaged over each kept row's interval, decimation.h) can read as a
// few milliseconds of delay. It is refined at the recording's own rate: the channel is fitted
// there with the delay (from the coarse value) and without it, from the decimated fit's values,
// on the same calibration and held-out rows. The delay stays, with its full-rate value, only
// when it lowers the full-rate held-out RMS by the share any effect must (min_improvement);
// otherwise it is left out. Either way the reason is kept in `refined`.
void refine_delay_at_full_rate(ChannelReport& c, const Recording& r, std::size_t held_out,
                               const Recording& analysed, std::size_t analysed_held_out,
                               const FitOptions& o) {
  auto& fx = c.final_fit.effects;
  const auto it = std::find_if(fx.begin(), fx.end(),
                               [](const Effect& e) { return e.spec->kind == EffectKind::kDelay; });
  if (it == fx.end() || c.change || held_out < 2 || held_out >= r.size()) return;
  const std::size_t index = static_cast<std::size_t>(it - fx.begin());
  const double coarse = it->values[0];
  std::vector<Effect> without = fx;
  without.erase(without.begin() + static_cast<std::ptrdiff_t>(index));
  Split split;
  split.calibration_end = held_out;
  const ChannelFit with_fit = fit_channel(*c.channel, r, split, c.final_fit.nominal, fx);
  const ChannelFit without_fit = fit_channel(*c.channel, r, split, c.final_fit.nominal, without);
  // The fit without the delay is the fit with a zero delay: a fit with it that ends worse on
  // its own calibration rows stopped in a local solution, and the delay is not shown to help.
  const bool converged = with_fit.rms_calibration <= without_fit.rms_calibration;
  const double improvement = converged && without_fit.rms_held_out > 0.0
                                 ? 1.0 - with_fit.rms_held_out / without_fit.rms_held_out
                                 : 0.0;
  double refined = coarse;
  for (const Effect& e : with_fit.effects)
    if (e.spec->kind == EffectKind::kDelay) refined = e.values[0];
  char note[260];
  if (improvement >= o.min_improvement) {
    it->values[0] = refined;
    // Its resolution as the full-rate fit reached it, then at least a row of the full rate.
    for (std::size_t e = 0; e < with_fit.effects.size() && e < with_fit.effect_sd.size(); ++e)
      if (with_fit.effects[e].spec->kind == EffectKind::kDelay &&
          index < c.final_fit.effect_sd.size())
        c.final_fit.effect_sd[index] = with_fit.effect_sd[e];
    widen_delay_by_row(c.final_fit, r);
    std::snprintf(note, sizeof note,
                  "transport delay refined at the full rate: %.4g s (decimated rows: %.4g s); "
                  "full-rate held-out RMS %.4g without it, %.4g with it",
                  refined, coarse, without_fit.rms_held_out, with_fit.rms_held_out);
    c.refined.push_back(note);
    return;
  }
  std::snprintf(note, sizeof note,
                "a transport delay of %.4g s on the decimated rows is left out: at the full rate "
                "the channel without it leaves a held-out RMS of %.4g, and a delay lowers that "
                "by %.1f %%, under %.0f %% (the decimation's timing, not the machine's)",
                coarse, without_fit.rms_held_out, 100.0 * improvement, 100.0 * o.min_improvement);
  c.refined.push_back(note);
  leave_out({index}, c, analysed, analysed_held_out);
}

// The channel's final fit solved again on `r` (the recording's own rate) from its values, the
// grid parameters kept, without effect `skip` (none when skip is past the effects).
ChannelFit refitted_at_rate(const ChannelReport& c, const Recording& r, const Split& split,
                            std::size_t skip = std::numeric_limits<std::size_t>::max()) {
  ChannelFit start = c.final_fit;
  if (skip < start.effects.size()) {
    start.effects.erase(start.effects.begin() + static_cast<std::ptrdiff_t>(skip));
    if (skip < start.effect_sd.size())
      start.effect_sd.erase(start.effect_sd.begin() + static_cast<std::ptrdiff_t>(skip));
  }
  c.channel->simulate(r, start.nominal, start.effects, start.prediction);
  return refit(*c.channel, r, split, start);
}

// Some values are taken from a fit at the recording's own rate, started from the decimated fit,
// on the same calibration rows; the effects earned their place on the decimated rows.
// - Stribeck's characteristic speed is a time-resolution parameter: after a breakaway the disc
//   passes through the first few hundredths of a rad/s within milliseconds, which the thinned
//   rows smear (the blind proof's hidden 0.05 rad/s read 0.039 on them, 0.047 at the full rate).
// - The clamp's relaxation branches are read through a closed loop: the clamp's controller
//   moves the roller on the load cell's reading, so the roller carries the force's past noise.
//   The anti-alias filter spreads each row's noise over its neighbours, which correlates the
//   filtered residual with the filtered roller, and least squares on such rows is biased by
//   about the noise's variance (closed-loop identification: Ljung, "System Identification",
//   2nd ed., 1999, sec. 13.4). At the full rate a row's noise is not yet in the roller, so the
//   estimate is not biased (a fast branch of 0.2 read 0.193 on the decimated rows at noise 2).
//   The clamp's hysteresis is read through the same loop.
// - A vibration's frequency and phase are time-resolution parameters too.
// The whole fit (the nominal's values moved with the effects' on the thinned rows) and its SDs
// come from that one refit; the grid parameters stay where they were found. `refitted` is that
// refit when confirm_at_full_rate already made it.
void refine_at_full_rate(ChannelReport& c, const Recording& r, std::size_t held_out,
                         const std::optional<ChannelFit>& refitted) {
  static constexpr std::array kRefined = {EffectKind::kStribeck, EffectKind::kRelaxation,
                                          EffectKind::kRelaxation2, EffectKind::kHysteresis,
                                          EffectKind::kPeriodic};
  const auto& fx = c.final_fit.effects;
  std::vector<std::size_t> refined;
  for (std::size_t e = 0; e < fx.size(); ++e)
    if (std::find(kRefined.begin(), kRefined.end(), fx[e].spec->kind) != kRefined.end())
      refined.push_back(e);
  if (refined.empty() || c.change || held_out < 2 || held_out >= r.size()) return;
  const std::vector<double>& y = r.at(c.channel->output());
  std::vector<double> start;
  c.channel->simulate(r, c.final_fit.nominal, fx, start);
  Split split;
  split.calibration_end = held_out;
  const ChannelFit at_rate = refitted ? *refitted : refitted_at_rate(c, r, split);
  // Ranked on the rows the fit compared: over all calibration rows a fit on every k-th row
  // may end a hair above its start (by about p/n of the noise's variance) without being worse.
  const double start_rms = rms_on_fitted_rows(start, y, split);
  const double end_rms = rms_on_fitted_rows(at_rate.prediction, y, split);
  char note[300];
  if (!(end_rms <= start_rms) || at_rate.effects.size() != fx.size() ||
      at_rate.effect_sd.size() != fx.size()) {
    std::snprintf(note, sizeof note,
                  "%s kept as fitted on the decimated rows: the fit at the full rate ended no "
                  "better on the calibration rows it compared (RMS %.4g against %.4g)",
                  fx[refined.front()].spec->name.c_str(), end_rms, start_rms);
    c.refined.push_back(note);
    return;
  }
  for (std::size_t e : refined) {
    std::string values;
    for (std::size_t k = 0; k < fx[e].values.size(); ++k) {
      std::snprintf(note, sizeof note, "%s%s %.4g (decimated rows: %.4g)", k > 0 ? ", " : "",
                    fx[e].spec->params[k].name.c_str(), at_rate.effects[e].values[k],
                    fx[e].values[k]);
      values += note;
    }
    c.refined.push_back(fx[e].spec->name + " refined at the full rate: " + values);
  }
  // The prediction on the analysed rows is made again by the caller (predict()).
  const double bic = c.final_fit.bic;
  c.final_fit = at_rate;
  c.final_fit.bic = bic;
}

// Every effect named on the thinned rows must also earn its place at the recording's own rate:
// the channel is refitted there with all of them, and without each in turn, from the thinned
// fit's values (grid parameters kept), on the same calibration rows; an effect whose absence
// leaves the held-out rows predicted as well (RMS no higher) is left out. The thinned rows can
// name what is not there: in a closed loop the anti-alias filter correlates the residual with
// the input (refine_at_full_rate above), and a synthetic PI-loop clamp at 4 N of noise named a
// play beside its relaxation that made the full-rate held-out RMS 14 % worse. The rule asks
// less than the thinned rows' (an RMS fall of min_improvement): at the full rate the noise the
// filter removed is back in both RMS. The delay has its own rule (refine_delay_at_full_rate),
// an effect another one needs (a Prony series' first term) is judged with it, and an effect
// given as known (--model) is not judged here. Returns the refit with every effect when it made
// one and left nothing out (refine_at_full_rate takes its values from it).
std::optional<ChannelFit> confirm_at_full_rate(ChannelReport& c, const Recording& r,
                                               std::size_t held_out, const Recording& analysed,
                                               std::size_t analysed_held_out) {
  const auto& fx = c.final_fit.effects;
  if (fx.empty() || c.change || held_out < 2 || held_out >= r.size()) return std::nullopt;
  std::vector<std::size_t> judged;
  for (std::size_t e = 0; e < fx.size(); ++e) {
    const EffectKind kind = fx[e].spec->kind;
    const bool needed = std::any_of(fx.begin(), fx.end(), [&](const Effect& other) {
      return other.spec->needs && *other.spec->needs == kind;
    });
    const bool named = std::any_of(c.chosen.begin(), c.chosen.end(), [&](const Candidate& k) {
      return k.effect == fx[e].spec->name;
    });
    if (kind != EffectKind::kDelay && !needed && named) judged.push_back(e);
  }
  if (judged.empty()) return std::nullopt;
  Split split;
  split.calibration_end = held_out;
  ChannelFit with = refitted_at_rate(c, r, split);
  std::vector<std::size_t> out;
  for (std::size_t e : judged) {
    const double without_rms = refitted_at_rate(c, r, split, e).rms_held_out;
    if (without_rms > with.rms_held_out) continue;
    char note[300];
    std::snprintf(note, sizeof note,
                  "%s, named on the decimated rows, is left out: at the full rate the channel "
                  "without it predicts the held-out rows as well (RMS %.4g without it, %.4g with "
                  "it)",
                  fx[e].spec->name.c_str(), without_rms, with.rms_held_out);
    c.refined.push_back(note);
    out.push_back(e);
  }
  if (out.empty()) return with;
  leave_out(out, c, analysed, analysed_held_out);
  return std::nullopt;
}

// A stiction beside a dry friction on the same channel: the friction's level at rest
// (Coulomb, plus Stribeck's extra) bounds what a dry friction holds (Armstrong-Helouvry et al.
// 1994, sec. 2: static friction is the force to begin motion). A breakaway at most that level
// (within two SDs of it) is the friction's own hold: a held torque never exceeds the
// breakaway, so the fitted breakaway is the largest held torque seen, a lower bound. Above it,
// the stiction is static friction of its own and stays named apart.
void judge_friction_hold(ChannelReport& c) {
  const auto& fx = c.final_fit.effects;
  std::optional<std::size_t> stiction, friction;
  for (std::size_t e = 0; e < fx.size(); ++e) {
    const EffectKind kind = fx[e].spec->kind;
    if (kind == EffectKind::kStiction) stiction = e;
    if (kind == EffectKind::kCoulomb || kind == EffectKind::kStribeck) friction = e;
  }
  if (!stiction || !friction) return;
  const Effect& f = fx[*friction];
  const bool stribeck = f.spec->kind == EffectKind::kStribeck;
  const double level = f.values[0] + (stribeck ? f.values[1] : 0.0);
  double level_var = 0.0;
  for (std::size_t k = 0; k < (stribeck ? 2u : 1u); ++k)
    level_var += std::pow(c.final_fit.effect_sd_of(*friction, k), 2);
  const double breakaway = fx[*stiction].values[1];
  const double bound = level + 2.0 * std::sqrt(level_var);
  if (breakaway > bound) return;
  const SignalDecl* out = find_signal(c.channel->output());
  const std::string unit = out != nullptr ? std::string(out->unit) : std::string();
  char note[300];
  std::snprintf(note, sizeof note,
                "the %s's own hold at rest: held up to %.4g %s, not above the friction's level "
                "at rest, %.4g +- %.2g %s (a static friction of its own would hold more)",
                f.spec->name.c_str(), breakaway, unit.c_str(), level, std::sqrt(level_var),
                unit.c_str());
  c.explained.push_back({*stiction, ChannelReport::ExplainedBy::Relation::kHoldAtRest,
                         c.channel->output() + ":" + f.spec->name, note});
}

// A dead zone (or the friction band, EffectKind::kLoopFriction) on the disc's speed beside a
// dry friction on its torque. A speed loop that is proportional (with any feedforward) closes
// on the disc's inertia J as a first-order lag of time constant T_d = J / K, K its stiffness in
// torque per unit of speed error (the speed channel's nominal form); a constant load torque F
// then holds the speed F / K = F T_d / J below its command (the loop's steady-state error;
// Ogata, Modern Control Engineering, ch. 5, type-0 systems). A band of that width is the
// friction seen through the loop, not an effect of its own: said so when the width is within
// two SDs (or 5 %) of F T_d / J, with F the friction's moving level, J the torque channel's
// inertia and T_d the speed channel's lag, each as fitted. An integrating loop leaves no such
// deficit, so no band.
void judge_speed_loop_deficit(FitReport& rep) {
  ChannelReport* speed = nullptr;
  const ChannelReport* torque = nullptr;
  for (auto& c : rep.channels) {
    if (c.channel->output() == "omega") speed = &c;
    if (c.channel->output() == "disc_torque") torque = &c;
  }
  if (speed == nullptr || torque == nullptr) return;
  std::optional<std::size_t> dead_zone, friction;
  for (std::size_t e = 0; e < speed->final_fit.effects.size(); ++e) {
    const EffectKind kind = speed->final_fit.effects[e].spec->kind;
    if (kind == EffectKind::kDeadZone || kind == EffectKind::kLoopFriction) dead_zone = e;
  }
  for (std::size_t e = 0; e < torque->final_fit.effects.size(); ++e) {
    const EffectKind kind = torque->final_fit.effects[e].spec->kind;
    if (kind == EffectKind::kCoulomb || kind == EffectKind::kStribeck) friction = e;
  }
  if (!dead_zone || !friction) return;
  auto value_sd = [](const ChannelFit& f, std::size_t e, std::size_t k) {
    return std::pair{f.effects[e].values[k], f.effect_sd_of(e, k)};
  };
  auto nominal_sd = [](const ChannelFit& f, std::size_t k) {
    return std::pair{f.nominal[k], k < f.nominal_sd.size() ? f.nominal_sd[k] : 0.0};
  };
  // The friction's moving level: Coulomb's, or Stribeck's Coulomb part (its extra is gone
  // within a few Stribeck speeds).
  const auto [level, level_sd] = value_sd(torque->final_fit, *friction, 0);
  const auto [inertia, inertia_sd] = nominal_sd(torque->final_fit, 0);  // J
  const auto [lag, lag_sd] = nominal_sd(speed->final_fit, 0);           // T_d
  const auto [width, width_sd] = value_sd(speed->final_fit, *dead_zone, 0);
  if (!(inertia > 0.0) || !(lag > 0.0) || !(level > 0.0)) return;
  const double predicted = level * lag / inertia;
  // First-order propagation of the three fitted values' SDs (treated as independent).
  const double rel2 =
      std::pow(level_sd / level, 2) + std::pow(lag_sd / lag, 2) + std::pow(inertia_sd / inertia, 2);
  const double predicted_sd = predicted * std::sqrt(rel2);
  const double combined_sd = std::hypot(width_sd, predicted_sd);
  const double off = std::abs(width - predicted);
  if (off > std::max(2.0 * combined_sd, 0.05 * predicted)) return;
  const std::string by =
      torque->channel->output() + ":" + torque->final_fit.effects[*friction].spec->name;
  const bool band_is_dead_zone =
      speed->final_fit.effects[*dead_zone].spec->kind == EffectKind::kDeadZone;
  char note[440];
  std::snprintf(note, sizeof note,
                "the disc torque's %s seen through the speed loop: a friction of %.4g N m against "
                "a proportional loop of time constant %.4g s on an inertia of %.4g kg m^2 holds "
                "the speed %.4g +- %.2g rad/s below its command (F T_d / J), where this band "
                "is %.4g%s",
                torque->final_fit.effects[*friction].spec->name.c_str(), level, lag, inertia,
                predicted, predicted_sd, width,
                band_is_dead_zone ? "; not a dead zone of the drive" : "; the same friction");
  speed->explained.push_back(
      {*dead_zone, ChannelReport::ExplainedBy::Relation::kThroughSpeedLoop, by, note});
}

Recording analysed_rows_of(const Recording& whole, const FitReport& rep) {
  if (rep.stopped_rows == 0 || rep.stopped_rows >= whole.size())
    return analysed_recording(whole, rep.options, rep.glitches);
  return analysed_recording(first_rows(whole, whole.size() - rep.stopped_rows), rep.options,
                            rep.glitches);
}

namespace {

// The channels whose columns the recording holds and whose output moves; the others are listed
// as unobservable, the known inputs each one takes as noted.
std::vector<const ChannelModel*> observable_channels(const Recording& r, FitReport& rep) {
  std::vector<const ChannelModel*> todo;
  for (const ChannelModel* ch : all_channels()) {
    bool ok = true;
    for (const auto& c : ch->needs()) ok = ok && r.has(c);
    // A channel whose output never moves says nothing about its physics.
    if (ok && signal_span(r.at(ch->output())) <= 0.0) ok = false;
    if (ok) {
      todo.push_back(ch);
      for (const auto& c : ch->known_inputs())
        if (r.has(c)) rep.known_inputs.push_back(c + " (" + ch->output() + ")");
    } else
      rep.unobservable.push_back(ch->subsystem() + ": " + ch->output());
  }
  if (todo.empty())
    throw RecordingError(r.file, 1,
                         "no observable subsystem: the header needs, for example, omega_cmd and "
                         "omega (disc drive), clamp_pos_mm and clamp_force (clamp), "
                         "depth_cmd_mm and depth_mm (depth), or v_ground and v_wheel (ground)");
  return todo;
}

// Each channel analysed on o.jobs threads, into rep.channels in the channels' own order.
void analyse_in_parallel(const std::vector<const ChannelModel*>& todo, const Recording& r,
                         const FitOptions& o, FitReport& rep) {
  rep.channels.resize(todo.size());
  // Longest first (the clamp's channel, with its many nominal starts, is about half of the
  // work): started last, it would run alone while the other worker idles.
  std::vector<std::size_t> order(todo.size());
  std::vector<std::size_t> cost(todo.size());
  for (std::size_t k = 0; k < todo.size(); ++k) {
    order[k] = k;
    cost[k] = todo[k]->candidates(r).size() * (1 + todo[k]->nominal_starts(r).size());
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  std::atomic<std::size_t> next{0};
  std::mutex progress;
  std::size_t done = 0;
  auto worker = [&] {
    for (std::size_t i = next++; i < todo.size(); i = next++) {
      const std::size_t k = order[i];
      rep.channels[k] = analyse_channel(*todo[k], r, o, rep.split);
      if (o.on_channel_done) {
        const std::lock_guard<std::mutex> lock(progress);
        o.on_channel_done(++done, todo.size(), todo[k]->output());
      }
    }
  };
  std::vector<std::thread> pool;
  for (int j = 1; j < std::min<int>(o.jobs, static_cast<int>(todo.size())); ++j)
    pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
}

// Vibration above the analysed rate, looked for in a channel's final residual at the
// recording's own rate (a 38 Hz tone is named at 38 Hz, not at its alias).
void seek_fast_tones(ChannelReport& c, const Recording& at_rate, std::size_t held_out,
                     double analysed_up_to_hz) {
  std::vector<double> pred;
  c.channel->simulate(at_rate, c.final_fit.nominal, c.final_fit.effects, pred);
  const std::vector<double>& y = at_rate.at(c.channel->output());
  // A tone is sought where the output moves: a leading stretch that holds the first value
  // exactly (a sensor not yet reporting: the load cell read 0.00 for the first 37 rows)
  // carries no vibration, and counted in the projection it took 0.24 % off a 38 Hz tone's
  // amplitude (2.5 of its SDs at 0.5 N of noise).
  std::size_t live = 0;
  while (live + 1 < y.size() && y[live + 1] == y[0]) ++live;
  const auto from = static_cast<std::ptrdiff_t>(live > 0 && live + 1 < held_out ? live + 1 : 0);
  const std::vector<double> t(at_rate.t.begin() + from, at_rate.t.end());
  std::vector<double> e = residual_of(pred, y);
  e.erase(e.begin(), e.begin() + from);
  c.fast_tones =
      find_fast_tones(t, e, analysed_up_to_hz, held_out - static_cast<std::size_t>(from));
  if (!c.fast_tones.empty() && c.chosen.empty() && !c.change)
    c.verdict =
        c.unexplained ? "effect(s) found; a residual is still unexplained" : "effect(s) found";
}

// What the decimation left to the recording's own rate: each channel's delay, its named
// effects confirmed and refined there, and the vibration above the analysed rate.
void refine_at_recording_rate(FitReport& rep, const Recording& full, const Recording& r,
                              const FitOptions& o) {
  const Recording clean = rep.glitches.empty() ? Recording{} : without_glitches(full, rep.glitches);
  const Recording& at_rate = rep.glitches.empty() ? full : clean;
  const auto held_out = static_cast<std::size_t>(
      std::lower_bound(at_rate.t.begin(), at_rate.t.end(), rep.held_out_from_s) -
      at_rate.t.begin());
  for (auto& c : rep.channels) {
    widen_delay_by_row(c.final_fit, r);  // as read on the thinned rows, unless refined below
    // Not beside a named process: its shape is fitted on the thinned rows, and a free-run
    // refit at the full rate without it gives the process's share back to the effects (a
    // relaxation beside the stems' spread read 0.21, 5.8 s for 0.3, 3 s; 0.29, 3.6 s beside).
    if (!c.disturbance) {
      refine_delay_at_full_rate(c, at_rate, held_out, r, rep.split.calibration_end, o);
      const std::optional<ChannelFit> confirmed =
          confirm_at_full_rate(c, at_rate, held_out, r, rep.split.calibration_end);
      refine_at_full_rate(c, at_rate, held_out, confirmed);
    }
    // The refined values' prediction on the analysed rows (the report's figures and plots).
    predict(*c.channel, r, rep.split, c.final_fit);
    seek_fast_tones(c, at_rate, held_out, rep.analysed_up_to_hz);
  }
}

}  // namespace

FitReport analyse(const Recording& whole, const FitOptions& o) {
  FitReport rep;
  rep.options = o;
  // Rows from a fault on are left out; with nothing before it, the usual messages follow.
  const std::size_t stopped = first_stopped_row(whole);
  std::optional<Recording> until_stopped;
  if (stopped >= 2 && stopped < whole.size()) {
    rep.stopped_state = whole.state[stopped];
    rep.stopped_at_s = whole.t[stopped];
    rep.stopped_rows = whole.size() - stopped;
    until_stopped = first_rows(whole, stopped);
  }
  const Recording& full = until_stopped ? *until_stopped : whole;
  rep.glitches = find_glitches(full, glitch_columns(full));
  const Recording r = analysed_recording(full, o, rep.glitches);
  rep.rate_hz = sample_rate_hz(full);
  const bool decimated = r.size() < full.size();
  rep.analysed_up_to_hz = decimated ? anti_alias_cutoff_hz(sample_rate_hz(r)) : 0.5 * rep.rate_hz;
  rep.analysed_rows = r.size();
  rep.file = r.file;
  rep.rows = full.size();
  rep.duration_s = r.t.back() - r.t.front();
  rep.split.calibration_end =
      static_cast<std::size_t>(static_cast<double>(r.size()) * (1.0 - o.held_out_fraction));
  rep.held_out_from_s = r.t[rep.split.calibration_end];
  analyse_in_parallel(observable_channels(r, rep), r, o, rep);
  if (decimated)
    refine_at_recording_rate(rep, full, r, o);
  else
    for (auto& c : rep.channels) widen_delay_by_row(c.final_fit, r);
  for (auto& c : rep.channels) judge_friction_hold(c);
  judge_speed_loop_deficit(rep);
  return rep;
}

}  // namespace planter::analysis
