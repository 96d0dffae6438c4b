// The library of named candidate effects: one entry each, holding how it acts, its bounds and
// its starts.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "analysis/decimation.h"
#include "analysis/effect_hooks.h"
#include "analysis/recent_two.h"
#include "analysis/residual_stats.h"
#include "analysis/tones.h"

namespace planter::analysis {

namespace {

// Where shift_in_time reads each row: between rows `from` and from + 1, `share` of the way
// (within (0, 1]), or row `from` itself where the share is negative (held at the ends).
struct ShiftPlan {
  std::vector<double> t;
  double shift_s = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::size_t> from;
  std::vector<double> share;
};

// The plan for the first n rows.
void plan_shift(const std::vector<double>& t, std::size_t n, double shift_s, ShiftPlan& plan) {
  plan.t.assign(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(n));
  plan.shift_s = shift_s;
  plan.from.resize(n), plan.share.resize(n);
  std::size_t j = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double when = t[k] - shift_s;  // rises with k, so j only moves forward
    if (when <= t[0] || when >= t[n - 1]) {
      plan.from[k] = when <= t[0] ? 0 : n - 1, plan.share[k] = -1.0;
      continue;
    }
    while (j + 1 < n && t[j + 1] < when) ++j;
    plan.from[k] = j, plan.share[k] = (when - t[j]) / (t[j + 1] - t[j]);
  }
}

}  // namespace

// The fits shift the same rows by the same time thousands of times (the drives' command path
// at every simulation, a delay at each step of another parameter): the plan of the last two
// shifts is kept, one cache per thread.
void shift_in_time(const Recording& r, double shift_s, std::vector<double>& u) {
  const std::size_t n = u.size();
  const auto same = [&](const ShiftPlan& p) {
    return p.shift_s == shift_s && p.t.size() == n && same_bits(p.t.data(), r.t.data(), n);
  };
  thread_local std::array<ShiftPlan, 2> plans;
  const ShiftPlan& plan =
      recent_two(plans, same, [&](ShiftPlan& fresh) { plan_shift(r.t, n, shift_s, fresh); });
  const std::vector<double> in = u;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = plan.from[k];
    const double a = plan.share[k];
    u[k] = a < 0.0 ? in[j] : in[j] + a * (in[j + 1] - in[j]);
  }
}

namespace {

// Where the play's follower starts in its gap, as a share of half the gap (see play()).
const ParamSpec kPlayStart{"start", "1 (-1 low end, +1 high end)", 0.0, -1.0, 1.0};
// The largest play searched: half the larger of the command's and the output's spans (a play
// wider than that would leave most moves unanswered). Both spans, so that the play before the
// drive and the one after it are searched over the same gaps: a 6 mm play on an opener that
// travelled 24 mm was out of reach of a fifth of the output's span (issue 32, item 6).
double play_upper(double in_span, double out_span, const std::vector<double>&) {
  return 0.5 * std::max(in_span, out_span);
}
// The widest band searched (a dead zone, a speed loop's friction deficit): 30 % of the
// command's span.
double band_upper(double in_span, double, const std::vector<double>&) { return 0.3 * in_span; }

// ---- How each effect acts (forms: control-engineering textbook nonlinearities, e.g.
// Slotine & Li, "Applied Nonlinear Control", ch. 5; friction after Armstrong-Helouvry; the
// Maxwell branch after Findley, "Creep and Relaxation of Nonlinear Viscoelastic Materials").

void delay(const Recording& r, const std::vector<double>& p, std::vector<double>& u) {
  if (p[0] > 0.0) shift_in_time(r, p[0], u);
}

// The control-textbook dead zone (Tao & Kokotovic, "Adaptive Control of Systems with Actuator
// and Sensor Nonlinearities", 1996, ch. 2): zero inside the band, the input less the band
// beyond it. (Symmetric here: the disc's commands do not reverse, so a reverse width could not
// be told from a recording of this machine.)
void dead_zone(const Recording&, const std::vector<double>& p, std::vector<double>& u) {
  if (p[0] <= 0.0) return;
  for (auto& v : u) v = std::abs(v) <= p[0] ? 0.0 : v - std::copysign(p[0], v);
}

// The play operator (Krasnosel'skii & Pokrovskii, "Systems with Hysteresis", 1989, ch. 1): the
// follower moves only when the driver has taken up half the gap either side of it. Its initial
// state is fitted: `start` places the follower at -1 (against the low end of the gap), 0
// (centred) or +1 (the high end). A gear train powers up against one end, and until the driver
// first crosses the gap the output sits half the gap off (issue 32, item 4).
void play(double gap, double start, std::vector<double>& u) {
  if (gap <= 0.0 || u.empty()) return;
  const double half = 0.5 * gap;
  double y = u[0] + std::clamp(start, -1.0, 1.0) * half;
  for (auto& v : u) {
    y = std::clamp(y, v - half, v + half);
    v = y;
  }
}

// Between the command and the drive (a coupling on the command side)...
void backlash(const Recording&, const std::vector<double>& p, std::vector<double>& u) {
  play(p[0], p[1], u);
}

// ... or between the drive and what the sensor sees (a gear or linkage after the actuator:
// the opener behind the depth actuator, the disc behind its motor). The brief does not fix
// which; both are tried and the fit says which side fits (issue 32, item 4).
void backlash_on_output(const OutputContext&, const std::vector<double>& p,
                        std::vector<double>& y) {
  play(p[0], p[1], y);
}

// A generalized Maxwell model (a Prony series; Findley, "Creep and Relaxation of Nonlinear
// Viscoelastic Materials", ch. 5): each branch i follows frac_i * y with time constant tau_i and
// is no longer carried, so a step in load gives the full force, which then decays towards
// (1 - sum frac_i) of it. The second branch, when the fit has one, acts here with the first.
void relaxation(const OutputContext& c, const std::vector<double>& p, std::vector<double>& y) {
  // At most two branches (fraction, tau): the first, and a second Prony term beside it.
  std::array<std::pair<double, double>, 2> branches{{{p[0], p[1]}, {0.0, 1.0}}};
  std::size_t count = 1;
  if (c.effects != nullptr)
    if (const Effect* second = find_effect(*c.effects, EffectKind::kRelaxation2))
      branches[count++] = {second->values[0], second->values[1]};
  // Each branch r' = (frac u - r) / tau is stepped exactly for an input linear between rows
  // (the first-order-hold equivalent: Franklin, Powell & Workman, "Digital Control of Dynamic
  // Systems", 3rd ed., sec. 6.3.2): r_k = d r_(k-1) + a u_k + b u_(k-1), with d = exp(-dt/tau),
  // a = frac (1 - g), b = frac (g - d), g = tau/dt (1 - d). An explicit Euler step read tau half
  // a row long: 3.015 s for 3 s at 33 Hz, outside the stated interval.
  std::array<double, 2> relaxed{}, d{}, a{}, b{};
  for (std::size_t n = 0; n < count; ++n) relaxed[n] = branches[n].first * y[0];
  double step_dt = -1.0, u_prev = y[0];
  for (std::size_t k = 0; k < y.size(); ++k) {
    const double dt = k > 0 ? c.r.t[k] - c.r.t[k - 1] : 0.0;
    // Rows are mostly evenly spaced, their times rounded: exp once per distinct step (to a
    // part in 1e9, far below what the fit resolves).
    if (std::abs(dt - step_dt) > 1e-9 * dt) {
      step_dt = dt;
      for (std::size_t n = 0; n < count; ++n) {
        const auto [frac, tau] = branches[n];
        d[n] = std::exp(-dt / tau);
        const double g = dt > 0.0 ? tau / dt * (1.0 - d[n]) : 1.0;
        a[n] = frac * (1.0 - g);
        b[n] = frac * (g - d[n]);
      }
    }
    const double u = y[k];
    double carried = u;
    for (std::size_t n = 0; n < count; ++n) {
      relaxed[n] = d[n] * relaxed[n] + a[n] * u + b[n] * u_prev;
      carried -= relaxed[n];
    }
    u_prev = u;
    // A contact force cannot pull: the relaxed branches lower the output towards zero, never
    // past it (an opened clamp reads nothing while the branches recover).
    y[k] = u >= 0.0 ? std::max(0.0, carried) : std::min(0.0, carried);
  }
}

// Hysteresis in the Bouc-Wen form (Wen, J. Eng. Mech. Div. ASCE 102(2), 1976; the survey of
// Ismail, Ikhouane & Rodellar, Arch. Comput. Methods Eng. 16, 2009), with n = 1 and
// beta = gamma = 1 / (2 delta): z' = (x' - |x'| z / 2 - x' |z| / 2) / delta. Along a move in one
// direction it is solved exactly: against the move z recovers linearly (d|z|/dx = 1/delta),
// with it z approaches +-1 as 1 - exp(-travel / delta). It adds H z.
//
// The rows where the path moves, each with its travel and direction: a held clamp is most of a
// recording's rows, where the state holds.
struct PathMoves {
  std::vector<std::size_t> row;
  std::vector<double> travel, sign;
};

PathMoves moves_along(const std::vector<double>& x) {
  PathMoves m;
  for (std::size_t k = 1; k < x.size(); ++k) {
    const double dx = x[k] - x[k - 1];
    if (dx == 0.0) continue;
    m.row.push_back(k);
    m.travel.push_back(std::abs(dx));
    m.sign.push_back(dx > 0.0 ? 1.0 : -1.0);
  }
  return m;
}

// The Bouc-Wen state at each of `rows` rows of a path that moves as `m` says.
std::vector<double> bouc_wen_path(const PathMoves& m, std::size_t rows, double delta) {
  std::vector<double> z(rows, 0.0);
  double held = 0.0;
  std::size_t from = 0;
  for (std::size_t i = 0; i < m.row.size(); ++i) {
    const std::size_t k = m.row[i];
    std::fill(z.begin() + static_cast<std::ptrdiff_t>(from),
              z.begin() + static_cast<std::ptrdiff_t>(k), held);
    const double s = m.sign[i];
    double u = s * held, travel = m.travel[i];  // u: z along the move
    if (u < 0.0) {
      const double to_zero = -u * delta;
      if (travel <= to_zero) {
        u += travel / delta;
        travel = 0.0;
      } else {
        travel -= to_zero;
        u = 0.0;
      }
    }
    if (travel > 0.0) u = 1.0 - (1.0 - u) * std::exp(-travel / delta);
    held = z[k] = s * u;
    from = k + 1;
  }
  std::fill(z.begin() + static_cast<std::ptrdiff_t>(std::min(from, rows)), z.end(), held);
  return z;
}

// The Bouc-Wen state along the path `x` for one delta, filtered and thinned as the output was
// when `stride` > 1 (only the ratio of cut-off to rate matters, hence rate 1). The solver moves
// one parameter at a time and only a change of delta or of the path changes the state: the
// states of the last two deltas are kept (a step in the height, the law's or another effect's
// parameter reuses the base point's, and so does the base after a step in delta), with the
// path's moves. One cache per thread: channels are analysed on several.
const std::vector<double>& hysteresis_state(const std::vector<double>& x, double delta,
                                            std::size_t stride) {
  struct Slot {
    std::vector<double> z;
    double delta = std::numeric_limits<double>::quiet_NaN();
    std::size_t stride = 0;
  };
  struct Cache {
    std::vector<double> x;
    PathMoves moves;
    std::array<Slot, 2> slots;
  };
  thread_local Cache c;
  if (!same_bits(x, c.x)) {
    c.x = x;
    c.moves = moves_along(x);
    for (Slot& s : c.slots) s.delta = std::numeric_limits<double>::quiet_NaN();
  }
  return recent_two(
             c.slots, [&](const Slot& s) { return delta == s.delta && stride == s.stride; },
             [&](Slot& s) {
               std::vector<double> z = bouc_wen_path(c.moves, x.size(), delta);
               s.z = stride > 1 ? thinned_as_filtered(std::move(z), stride, 1.0) : std::move(z);
               s.delta = delta;
               s.stride = stride;
             })
      .z;
}

void hysteresis(const OutputContext& c, const std::vector<double>& p, std::vector<double>& y) {
  if (c.displacement == nullptr || p[0] == 0.0) return;
  const double height = p[0];
  const std::vector<double>& z = hysteresis_state(*c.displacement, p[1], c.displacement_stride);
  for (std::size_t k = 0; k < y.size() && k < z.size(); ++k) y[k] += height * z[k];
}

void sag(const OutputContext& c, const std::vector<double>& p, std::vector<double>& y) {
  if (c.load == nullptr) return;
  for (std::size_t k = 0; k < y.size(); ++k) y[k] -= p[0] * (*c.load)[k] / 1000.0;
}

void slip_with_draft(const OutputContext& c, const std::vector<double>& p, std::vector<double>& y) {
  if (c.load == nullptr) return;
  for (std::size_t k = 0; k < y.size(); ++k) y[k] *= 1.0 - p[0] * (*c.load)[k] / 1000.0;
}

// The sign of the speed, smoothed over kFrictionSmoothing_radps: sharp, as the disc turns slowly.
constexpr double kFrictionSmoothing_radps = 0.005;
double friction_sign(double w) { return std::tanh(w / kFrictionSmoothing_radps); }

void coulomb(const OutputContext& c, const std::vector<double>& p, std::vector<double>& y) {
  if (c.speed == nullptr) return;
  for (std::size_t k = 0; k < y.size(); ++k) y[k] += p[0] * friction_sign((*c.speed)[k]);
}

// Stribeck friction in its usual exponential form (Armstrong-Helouvry, Dupont & Canudas de
// Wit, Automatica 30(7), 1994, eq. 1): the Coulomb level plus an extra that fades with speed.
// With no extra it is Coulomb friction, which it must then beat by a margin (mismatch.cpp).
void stribeck(const OutputContext& c, const std::vector<double>& p, std::vector<double>& y) {
  if (c.speed == nullptr) return;
  for (std::size_t k = 0; k < y.size(); ++k) {
    const double w = (*c.speed)[k] / p[2];
    y[k] += (p[0] + p[1] * std::exp(-w * w)) * friction_sign((*c.speed)[k]);
  }
}

void scale(const OutputContext&, const std::vector<double>& p, std::vector<double>& y) {
  for (auto& v : y) v *= 1.0 + p[0];
}

void offset(const OutputContext&, const std::vector<double>& p, std::vector<double>& y) {
  for (auto& v : y) v += p[0];
}

void drift(const OutputContext& c, const std::vector<double>& p, std::vector<double>& y) {
  for (std::size_t k = 0; k < y.size(); ++k) y[k] += p[0] * (c.r.t[k] - c.r.t[0]);
}

// A sinusoid as the recorded one reached these rows: through the anti-alias filter when the
// recording was thinned (decimation.h), so the amplitude stated is the machine's.
void periodic(const OutputContext& c, const std::vector<double>& p, std::vector<double>& y) {
  const double amplitude = p[0] * anti_alias_gain(c.r, p[1]);
  for (std::size_t k = 0; k < y.size(); ++k)
    y[k] += amplitude * std::sin(2.0 * std::numbers::pi * p[1] * c.r.t[k] + p[2]);
}

// A hard limit on the output (a load cell's range, an amplifier's rail): the reading stops at
// the limit however far the quantity goes on (the saturation nonlinearity of Slotine & Li,
// ch. 5). Only the upper one: the machine's loads push one way.
void saturation(const OutputContext&, const std::vector<double>& p, std::vector<double>& y) {
  if (p[0] <= 0.0) return;
  for (auto& v : y) v = std::min(v, p[0]);
}

void quantisation(const OutputContext&, const std::vector<double>& p, std::vector<double>& y) {
  if (p[0] <= 0.0) return;
  for (auto& v : y) v = p[0] * std::round(v / p[0]);
}

// The periodic effect starts at the residual spectrum's peak: a coarse scan up to the analysed
// rate's own Nyquist frequency, then a fine search around the best bin (over a long record a
// small frequency error turns into a large phase error). Faster tones are removed before
// decimation and looked for at the recording's rate (tones.h).
std::vector<double> periodic_start(const Recording& r, const std::vector<double>& residual) {
  const std::size_t n = std::min<std::size_t>(residual.size(), 40000);
  const double duration = r.t[n - 1] - r.t[0];
  const double f_max = 0.45 * static_cast<double>(n - 1) / duration;
  const double coarse = std::max(0.02, 0.5 / duration);
  double best_f = 1.0, best_a = -1.0;
  for (double f = 0.2; f <= f_max; f += coarse) {
    const double a = project_tone(r.t, residual, n, f).amplitude;
    if (a > best_a) best_a = a, best_f = f;
  }
  const Tone tone = refine_tone(r.t, residual, n, best_f - coarse, best_f + coarse);
  return {tone.amplitude, tone.frequency_hz, tone.phase_rad};
}

// One entry per effect, in the order they are applied: input effects, then output effects;
// the two that change a channel's dynamics last.
const std::vector<EffectSpec>& library() {
  static const std::vector<EffectSpec> lib = [] {
    std::vector<EffectSpec> l;
    auto add = [&l](EffectSpec e) { l.push_back(std::move(e)); };
    add({.kind = EffectKind::kDelay,
         .name = "transport delay",
         .signature = "residual follows the input's derivative",
         .params = {{"delay_s", "s", 0.0, 0.0, 0.5, true}},
         .on_input = delay,
         .separating_experiment = "a step of the command: a delay shifts the whole response late, "
                                  "a slower lag only rounds it"});
    add({.kind = EffectKind::kDeadZone,
         .name = "dead zone",
         .signature = "no response to small inputs, the band missing from larger ones",
         .params = {{"width", "input units", 0.0, 0.0, 0.0, true}},
         .on_input = dead_zone,
         .grid_upper = band_upper,
         .separating_experiment = "a slow ramp of the command up from zero: a dead zone answers "
                                  "only past its band, and then short by the band"});
    add({.kind = EffectKind::kBacklash,
         .name = "backlash (play)",
         .signature = "lag at every reversal of the input",
         .params = {{"gap", "input units", 0.0, 0.0, 0.0, true}, kPlayStart},
         .on_input = backlash,
         .grid_upper = play_upper,
         .separating_experiment =
             "a command that reverses slowly: play shows only just after each reversal"});
    add({.kind = EffectKind::kBacklashOutput,
         .name = "backlash (play) after the drive",
         .signature = "the output holds still after every reversal of the drive",
         .params = {{"gap", "output units", 0.0, 0.0, 0.0, true}, kPlayStart},
         .on_output = backlash_on_output,
         .grid_upper = play_upper,
         .separating_experiment = "a command that reverses slowly, recorded at the drive and at "
                                  "the load: play on the command side delays the drive too, play "
                                  "after it only the load"});
    add({.kind = EffectKind::kRelaxation,
         .name = "viscoelastic relaxation (creep) of the clamp",
         .signature = "output decays towards a lower level after each load change",
         .params = {{"fraction", "1", 0.1, 0.0, 0.9}, {"tau_s", "s", 2.0, 0.05, 60.0}},
         .on_output = relaxation,
         .extra_starts = {{0.2, 0.5}, {0.2, 3.0}, {0.2, 15.0}},
         .separating_experiment = "the clamp held closed at one position for a minute or more: "
                                  "relaxation settles, drift keeps growing"});
    add({.kind = EffectKind::kRelaxation2,
         .name = "viscoelastic relaxation, a second time scale (Prony series)",
         .signature = "after a load change, a fast decay and then a slow one",
         .params = {{"fraction2", "1", 0.1, 0.0, 0.9}, {"tau2_s", "s", 30.0, 0.05, 3600.0}},
         .extra_starts = {{0.1, 0.5}, {0.1, 10.0}, {0.1, 100.0}},
         .needs = EffectKind::kRelaxation,
         .separating_experiment = "the clamp held closed at one position for ten minutes or "
                                  "more: each time scale settles in its turn"});
    add({.kind = EffectKind::kHysteresis,
         .name = "hysteresis of the clamp (Bouc-Wen)",
         .signature = "closing and opening give different forces at the same position",
         // A passive clamp dissipates: the loading branch lies above the unloading one (H > 0).
         .params = {{"height", "output units", 0.0, 0.0, 2.0, false, true},
                    {"delta", "input units", 0.5, 0.01, 100.0}},
         .on_output = hysteresis,
         .extra_starts = {{0.0, 0.1}, {0.0, 2.0}},
         .separating_experiment = "the clamp closed and opened slowly over its range: "
                                  "hysteresis draws a loop whose width does not depend on the "
                                  "speed, relaxation one that does"});
    add({.kind = EffectKind::kSag,
         .name = "actuator compliance (sag) under load",
         .signature = "residual proportional to the load on the actuator",
         .params = {{"sag_per_kN", "output units/kN", 0.0, -100.0, 100.0}},
         .on_output = sag,
         .separating_experiment = "one depth held while the draft changes (a lighter and a heavier "
                                  "soil): sag follows the load"});
    add({.kind = EffectKind::kSlipWithDraft,
         .name = "wheel slip growing with draft load",
         .signature = "speed deficit proportional to speed times opener draft",
         .params = {{"slip_per_kN", "1/kN", 0.0, -0.5, 0.5}},
         .on_output = slip_with_draft,
         .separating_experiment = "the same stretch driven with the opener lowered and raised: "
                                  "slip with draft goes with the draft"});
    // Friction opposes motion: the drive pays it in the direction of motion, never gets it.
    const std::string friction_sweep =
        "a slow speed sweep through zero: Coulomb friction is one level at every speed, "
        "Stribeck friction peaks near standstill";
    add({.kind = EffectKind::kCoulomb,
         .name = "Coulomb friction",
         .signature = "a step in the residual at each speed reversal",
         .params = {{"coulomb", "output units", 0.0, 0.0, 2.0, false, true}},
         .on_output = coulomb,
         .separating_experiment = friction_sweep});
    add({.kind = EffectKind::kStribeck,
         .name = "Stribeck friction",
         .signature = "extra resistance at low speed",
         .params = {{"coulomb", "output units", 0.0, 0.0, 2.0, false, true},
                    {"stribeck_extra", "output units", 0.0, 0.0, 2.0, false, true},
                    // Below four times the sign's smoothing, a Stribeck speed would only
                    // reshape that smoothing (a Coulomb step would pass for Stribeck).
                    {"stribeck_speed", "input units", 0.1, 4.0 * kFrictionSmoothing_radps, 5.0}},
         .on_output = stribeck,
         .extends = EffectKind::kCoulomb,
         .separating_experiment = friction_sweep,
         .size_param = 1});  // what it adds to Coulomb's: the extra at rest
    add({.kind = EffectKind::kWheelRadius,
         .name = "wrong effective wheel radius",
         .signature = "speed error proportional to speed",
         .params = {{"radius_error", "1", 0.0, -0.3, 0.3}},
         .on_output = scale,
         .separating_experiment =
             "a measured distance driven at two speeds: a radius error is the same share at both"});
    add({.kind = EffectKind::kGain,
         .name = "sensor gain error",
         .signature = "residual proportional to the output",
         .params = {{"gain_error", "1", 0.0, -0.5, 0.5}},
         .on_output = scale,
         .separating_experiment =
             "two held loads of known size: a gain error grows with the load, an offset does not"});
    add({.kind = EffectKind::kOffset,
         .name = "sensor offset",
         .signature = "a constant residual",
         .params = {{"offset", "output units", 0.0, -2.0, 2.0, false, true}},
         .on_output = offset,
         .separating_experiment = "readings at zero load (the clamp open, the disc at rest, the "
                                  "machine stopped long enough for the draft to ease): an offset "
                                  "reads there too"});
    add({.kind = EffectKind::kDrift,
         .name = "sensor drift",
         .signature = "a residual growing linearly with time",
         .params = {{"drift_per_s", "output units/s", 0.0, -1.0, 1.0, false, true}},
         .on_output = drift,
         .separating_experiment = "the machine held still for several minutes: drift keeps "
                                  "growing, relaxation settles"});
    add({.kind = EffectKind::kPeriodic,
         .name = "periodic disturbance (vibration)",
         .signature = "a peak in the residual spectrum",
         .params = {{"amplitude", "output units", 0.0, 0.0, 2.0, false, true},
                    {"frequency_hz", "Hz", 1.0, 0.01, 1e4},
                    {"phase_rad", "rad", 0.0, -20.0, 20.0}},
         .on_output = periodic,
         .start = periodic_start,
         .separating_experiment =
             "a run at another engine or disc speed: a vibration moves with its source"});
    add({.kind = EffectKind::kSaturation,
         .name = "hard limit of the output (saturation)",
         .signature = "a flat top where the output would go on rising",
         // On a grid up to the largest recorded value: a sensor that saturates records its
         // limit, and no more.
         .params = {{"limit", "output units", 0.0, 0.0, 0.0, true}},
         .on_output = saturation,
         .grid_upper =
             [](double, double, const std::vector<double>& y) {
               return y.empty() ? 0.0 : *std::max_element(y.begin(), y.end());
             },
         .separating_experiment = "a load beyond the limit read by a second sensor: the "
                                  "saturating one stays flat while the other rises",
         .size_param = -1});
    add({.kind = EffectKind::kQuantisation,
         .name = "quantisation",
         .signature = "a staircase residual, uniform within a step",
         .params = {{"step", "output units", 0.0, 0.0, 0.0, true}},
         .on_output = quantisation,
         // A sensor that quantises records values on its step's grid: a step coarser than the
         // grid the recorded values lie on would be a staircase the recording does not have.
         .grid_upper =
             [](double, double out_span, const std::vector<double>& y) {
               return std::min(0.05 * out_span, 1.5 * value_grid(y));
             },
         .separating_experiment =
             "a slow ramp of the output: a quantised sensor steps in one step size"});
    // Applied inside the channels whose dynamics they change (channels.cpp).
    add({.kind = EffectKind::kRateLimit,
         .name = "rate limit",
         .signature = "residual at large steps, linear ramps",
         .params = {{"rate_per_s", "output units/s", 1.0, 1e-3, 1e4}},
         .separating_experiment = "a large step of the command: a rate limit ramps at one slope "
                                  "whatever the step's size",
         .size_param = -1});
    // A dry friction F under a proportional speed loop of stiffness K holds the speed F / K short
    // of its command while it moves (the loop's steady-state error for a constant load; Ogata,
    // "Modern Control Engineering", ch. 5, type-0 systems) and holds it at rest while the
    // command's effort is within F (Armstrong-Helouvry, Dupont & Canudas de Wit, Automatica
    // 30(7), 1994: Coulomb friction with sticking). Moving, it is a dead zone of width F / K; a
    // stop tells them apart: the friction brings the speed to rest in a finite time, a dead
    // zone lets it decay towards zero. Applied inside the speed channel's lag (channels.cpp).
    add({.kind = EffectKind::kLoopFriction,
         .name = "dry friction under the speed loop",
         .signature = "the speed short of its command by one band, and stops sooner than the lag",
         .params = {{"width", "input units", 0.0, 0.0, 0.0, true}},
         .grid_upper = band_upper,
         .separating_experiment =
             "a stop from speed: friction brings the disc to rest in a finite time, a dead zone of "
             "the drive lets the speed decay towards zero with the loop's lag"});
    add({.kind = EffectKind::kStiction,
         .name = "stiction (the disc held by static friction)",
         .signature = "torque while the speed is zero and the command is not",
         .params = {{"effort_gain", "N m s/rad", 10.0, 0.0, 1e3},
                    {"breakaway", "N m", 1.0, 0.0, 100.0}},
         .separating_experiment = "starts from rest with a slowly rising command: stiction holds "
                                  "the disc until breakaway",
         .size_param = 1});
    return l;
  }();
  return lib;
}

}  // namespace

const EffectSpec& effect_spec(EffectKind kind) {
  for (const auto& e : library())
    if (e.kind == kind) return e;
  throw std::logic_error("effect kind without an entry in the library");
}

const Effect* find_effect(const std::vector<Effect>& fx, EffectKind kind) {
  for (const auto& e : fx)
    if (e.spec->kind == kind) return &e;
  return nullptr;
}

void order_prony_terms(std::vector<Effect>& fx, std::vector<std::vector<double>>& sd) {
  std::size_t one = fx.size(), two = fx.size();
  for (std::size_t e = 0; e < fx.size(); ++e) {
    if (fx[e].spec->kind == EffectKind::kRelaxation) one = e;
    if (fx[e].spec->kind == EffectKind::kRelaxation2) two = e;
  }
  if (one == fx.size() || two == fx.size() || fx[one].values[1] <= fx[two].values[1]) return;
  std::swap(fx[one].values, fx[two].values);
  if (one < sd.size() && two < sd.size()) std::swap(sd[one], sd[two]);
}

std::vector<double> transform_input(const Recording& r, const std::vector<double>& u,
                                    const std::vector<Effect>& fx) {
  std::vector<double> out = u;
  for (const EffectSpec& spec : library()) {
    if (spec.on_input == nullptr) continue;
    if (const Effect* e = find_effect(fx, spec.kind)) spec.on_input(r, e->values, out);
  }
  return out;
}

void apply_output(const Recording& r, const std::vector<Effect>& fx,
                  const std::vector<double>* load, const std::vector<double>* speed,
                  std::vector<double>& y, const std::string& displacement) {
  OutputContext context{r, load, speed, &fx};
  if (const auto full_rate = r.travel.find(displacement); full_rate != r.travel.end()) {
    context.displacement = &full_rate->second;
    context.displacement_stride = r.decimation_stride;
  } else if (!displacement.empty()) {
    context.displacement = &r.at(displacement);
  }
  for (const EffectSpec& spec : library()) {
    if (spec.on_output == nullptr) continue;
    if (const Effect* e = find_effect(fx, spec.kind)) spec.on_output(context, e->values, y);
  }
}

}  // namespace planter::analysis
