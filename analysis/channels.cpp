// The nominal structures of docs/recording-format.md as channels: ground, disc drive (speed and
// torque), clamp, depth (position and draft).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <random>

#include "analysis/at_rest.h"
#include "analysis/channel_model.h"
#include "analysis/decimation.h"
#include "analysis/draft_factors.h"
#include "analysis/effect_hooks.h"
#include "analysis/recent_two.h"
#include "analysis/residual_stats.h"
#include "sim/soil/opener_draft.h"

namespace planter::analysis {
namespace {

std::vector<const EffectSpec*> specs(std::initializer_list<EffectKind> kinds) {
  std::vector<const EffectSpec*> out;
  for (EffectKind k : kinds) out.push_back(&effect_spec(k));
  return out;
}

// `always`, and `driven` too when the recording has the signal that drives it.
std::vector<const EffectSpec*> specs(const Recording& r, std::initializer_list<EffectKind> always,
                                     const char* signal, EffectKind driven) {
  std::vector<const EffectSpec*> out = specs(always);
  if (r.has(signal)) out.push_back(&effect_spec(driven));
  return out;
}

// First-order lag y' = (u - y) / T, u limited to +-u_max, y' to the rate limit if any. A dry
// friction under the loop (EffectKind::kLoopFriction, effects.cpp) takes its band w off the
// target in the direction of motion, holds the state at rest while |u| <= w, and stops it where
// it would cross zero (the next row starts it again if the command is beyond the band).
void lag(const Recording& r, const std::vector<double>& u, double tau, double u_max,
         const std::vector<Effect>& fx, double y0, std::vector<double>& y) {
  const Effect* rate = find_effect(fx, EffectKind::kRateLimit);
  const Effect* dry = find_effect(fx, EffectKind::kLoopFriction);
  const double band = dry != nullptr ? std::max(0.0, dry->values[0]) : 0.0;
  y.assign(u.size(), y0);
  double state = y0;
  for (std::size_t k = 1; k < u.size(); ++k) {
    const double dt = r.t[k] - r.t[k - 1];
    double target = std::clamp(u[k - 1], -u_max, u_max);
    if (band > 0.0) {
      const double moving = state != 0.0 ? state : (std::abs(target) > band ? target : 0.0);
      if (moving == 0.0) {  // held at rest
        y[k] = state;
        continue;
      }
      target -= std::copysign(band, moving);
    }
    const double a = 1.0 - std::exp(-dt / tau);  // exact for a held input
    double step = a * (target - state);
    if (rate) step = std::clamp(step, -rate->values[0] * dt, rate->values[0] * dt);
    const double next = state + step;
    state = band > 0.0 && state != 0.0 && next * state < 0.0 ? 0.0 : next;
    y[k] = state;
  }
}

// CiA 301's synchronous PDOs: a drive acts on a command at the SYNC after the row that recorded
// it, one SYNC period later, and holds it for a period: a staircase whose mean runs half a period
// behind its rows. The discrete lags below hold each analysed sample's input over the next
// interval, which puts half an analysed interval of delay into the model. The command is shifted
// by the difference, 1.5 SYNC periods less half an analysed interval: one period at the full
// rate, none when three rows are averaged into one (decimation.h). A recording that declares
// its SYNC period (sync_period_s, docs/recording-format.md) carries the path; one that does not
// is fitted as before, and a path there can show as a transport delay.
std::vector<double> command_at_drive(const Recording& r, const std::vector<double>& command) {
  const double sync_s = r.sync_period_s();
  const std::size_t n = command.size();
  if (sync_s <= 0.0 || n < 2) return command;
  const double sample_s = (r.t[n - 1] - r.t[0]) / static_cast<double>(n - 1);
  std::vector<double> out = command;
  shift_in_time(r, 1.5 * sync_s - 0.5 * sample_s, out);
  return out;
}

// A column at time `when_s` (linear between rows).
double at_time(const Recording& r, const std::vector<double>& v, double when_s) {
  const std::size_t n = v.size();
  if (when_s <= r.t[0]) return v[0];
  if (when_s >= r.t[n - 1]) return v[n - 1];
  const auto it = std::upper_bound(r.t.begin(), r.t.end(), when_s);
  const std::size_t j = static_cast<std::size_t>(it - r.t.begin()) - 1;
  const double a = (when_s - r.t[j]) / (r.t[j + 1] - r.t[j]);
  return v[j] + a * (v[j + 1] - v[j]);
}

// The encoder speed as the firmware makes it (firmware/sensing/ground_speed_estimator.cpp):
// the distance over the last window of edges divided by its time, where the window (2 lag_s,
// the estimate then lags about half of it) is cut short by the motion's first edge; a new
// estimate at each edge, held to the next; one count over the gap at the first edge after a
// stop; at most one count over the time since the last edge, so that it decays as 1/t after a
// stop and reads 0 before the first edge. Where the recording holds wheel_counts, the rows at
// which the count changed give the edges (to a row), and a count's length is the distance
// v_wheel covered over the counts. Each edge is placed within the interval before the row
// that shows it by the distance the wheel rolled (edge_times below).
// Without the counts, or on decimated rows (v_wheel low-pass filtered, the edges thinned: the
// per-edge behaviour is below what they resolve), the speed `lag_s` late.

// The largest (or, negated, smallest) of v over rows k - half to k + half, for each k: a
// monotonic queue of candidates, each row pushed and popped once.
std::vector<double> sliding_max(const std::vector<double>& v, std::size_t half) {
  const std::size_t n = v.size();
  std::vector<double> out(n);
  std::deque<std::size_t> q;
  for (std::size_t k = 0, next = 0; k < n; ++k) {
    for (; next < n && next <= k + half; ++next) {
      while (!q.empty() && v[q.back()] <= v[next]) q.pop_back();
      q.push_back(next);
    }
    while (q.front() + half < k) q.pop_front();
    out[k] = v[q.front()];
  }
  return out;
}

// A count's length in a cumulative distance's units: the slope of distance on count over the
// rows that show an edge (least squares), `otherwise` where that slope is not positive. Its
// ends do not bias it: neither the encoder's phase at either end nor a distance that keeps
// growing after the last edge (the estimate's 1/t decay, integrated).
double length_per_count(const std::vector<double>& counts, const std::vector<double>& distance,
                        double otherwise) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, edges = 0.0;
  for (std::size_t k = 1; k < counts.size(); ++k) {
    if (counts[k] == counts[k - 1]) continue;
    const double c = counts[k] - counts.front(), d = distance[k] - distance.front();
    sx += c, sy += d, sxx += c * c, sxy += c * d, edges += 1.0;
  }
  const double spread = sxx - sx * sx / std::max(edges, 1.0);
  const double slope = spread > 0.0 ? (sxy - sx * sy / edges) / spread : 0.0;
  return slope > 0.0 ? slope : otherwise;
}

// When, within the interval before the row that shows it, each row's last edge came. The
// recording gives edges to a row (10 ms at 100 Hz), and as a push stops, the firmware's bound
// of one count over the time since the last edge moves by half for an edge placed at the
// interval's start rather than its end. The rolled distance (v_ground less the known slip)
// places it. In counts of the wheel's own length (the slope of distance on count over the
// edges), position p, a row's count is floor(p - phase): each row bounds the encoder's
// phase to an interval one count wide, and the rows within kWindow_s of an edge overlap where
// the phase is, to a fraction of a count once the edges have fallen at several places within
// their rows (a longer reach lets the rolled distance drift from the wheel: a count over
// hil-commissioning's 10 s of creeping). The edge is where p crosses its count plus that
// phase. The controller's columns may be stamped later than the independent speed sensor's
// (planter-sim stamps a row after the plant step that the controller's tick began: one row):
// p is taken `shift` earlier, from 0 to two rows in eighths, the shift whose intervals overlap
// best at the edges (on hil-commissioning's push, the intervals miss each other by 0.11 counts
// at one row, 0.84 at none, 1.03 at two). Where they miss by more than kMaxGap counts (the
// rolled distance does not follow the wheel), and at reversals, an edge stays at its row's
// end. `at`: 0 where a row shows no edge; `shift_s`: the rolled distance's time is the row's
// less this (what the firmware's window over the edges spans of the distance).
struct EdgeTimes {
  std::vector<double> at;
  double shift_s = 0.0;
};
EdgeTimes edge_times(const Recording& r, const std::vector<double>& counts,
                     const std::vector<double>& rolled, const std::vector<double>& travelled) {
  constexpr double kWindow_s = 0.25, kMaxGap = 0.5;
  const std::size_t n = counts.size();
  EdgeTimes out;
  std::vector<double>& edge = out.at;
  edge.assign(n, 0.0);
  for (std::size_t k = 1; k < n; ++k)
    if (counts[k] != counts[k - 1]) edge[k] = r.t[k];
  const double distance = travelled.back() - travelled.front();
  const double moved = counts.back() - counts.front();
  if (n < 2 || !(moved > 0.0) || !(distance > 0.0)) return out;
  // (The distance over the counts recorded is off by up to a count's share of the whole, the
  // encoder's phase at either end, and a phase that drifts by a count misplaces the shift.)
  const double per_count = length_per_count(counts, travelled, distance / moved);
  const double row_s = (r.t[n - 1] - r.t[0]) / static_cast<double>(n - 1);
  const auto half = std::max<std::size_t>(2, static_cast<std::size_t>(kWindow_s / row_s));
  struct Placing {
    double gap = std::numeric_limits<double>::infinity();  // summed over the edges
    double shift_s = 0.0;
    std::vector<double> p, lo, hi;
  };
  Placing best;
  std::vector<double> lower(n), minus_upper(n);
  for (int eighth = 0; eighth <= 16; ++eighth) {
    const double shift_s = 0.125 * eighth * row_s;
    Placing c;
    c.shift_s = shift_s;
    c.p.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      c.p[k] = (at_time(r, travelled, r.t[k] - shift_s) - travelled.front()) / per_count;
      // floor(p - phase) = count: phase in (p - count - 1, p - count].
      minus_upper[k] = -(c.p[k] - (counts[k] - counts.front()));
      lower[k] = -minus_upper[k] - 1.0;
    }
    c.lo = sliding_max(lower, half);
    c.hi = sliding_max(minus_upper, half);
    for (double& h : c.hi) h = -h;
    c.gap = 0.0;
    for (std::size_t k = 1; k < n; ++k)
      if (counts[k] != counts[k - 1]) c.gap += std::max(c.lo[k] - c.hi[k], 0.0);
    if (c.gap < best.gap) best = std::move(c);
  }
  // Within a row the position is the cubic through both ends' positions and speeds (Hermite):
  // exact while the speed changes linearly, as it does through a braking row, where a straight
  // line between the rows put the stop's last edge 3-4 ms off. The crossing by bisection.
  for (std::size_t k = 1; k < n; ++k) {
    const double p0 = best.p[k - 1], p1 = best.p[k];
    if (counts[k] <= counts[k - 1] || !(p1 > p0) || best.lo[k] - best.hi[k] > kMaxGap) continue;
    const double crossing = (counts[k] - counts.front()) + 0.5 * (best.lo[k] + best.hi[k]);
    const double h = r.t[k] - r.t[k - 1];
    const double u0 = at_time(r, rolled, r.t[k - 1] - best.shift_s) / per_count * h;
    const double u1 = at_time(r, rolled, r.t[k] - best.shift_s) / per_count * h;
    auto position = [&](double f) {
      const double f2 = f * f, f3 = f2 * f;
      return (2 * f3 - 3 * f2 + 1) * p0 + (f3 - 2 * f2 + f) * u0 + (3 * f2 - 2 * f3) * p1 +
             (f3 - f2) * u1;
    };
    double lo_f = 0.0, hi_f = 1.0;
    for (int it = 0; it < 30; ++it) {
      const double mid = 0.5 * (lo_f + hi_f);
      (position(mid) < crossing ? lo_f : hi_f) = mid;
    }
    edge[k] = r.t[k - 1] + 0.5 * (lo_f + hi_f) * h;
  }
  out.shift_s = best.shift_s;
  return out;
}

void as_estimated(const Recording& r, const std::vector<double>& rolled, double lag_s,
                  std::vector<double>& y) {
  const Effect lag{&effect_spec(EffectKind::kDelay), {lag_s}};
  const double travelled_counts =
      r.has("wheel_counts") ? std::abs(r.at("wheel_counts").back() - r.at("wheel_counts")[0]) : 0;
  if (travelled_counts < 10.0 || r.decimation_stride > 1) {  // < 10: a count's length unknown
    y = transform_input(r, rolled, {lag});
    return;
  }
  const auto& counts = r.at("wheel_counts");
  const auto& v = r.at("v_wheel");
  // The firmware's count length in v_wheel's own units, from the distance v_wheel covers.
  std::vector<double> estimated_m(v.size(), 0.0);
  for (std::size_t k = 1; k < v.size(); ++k)
    estimated_m[k] = estimated_m[k - 1] + std::abs(v[k]) * (r.t[k] - r.t[k - 1]);
  const double m_per_count =
      length_per_count(counts, estimated_m, estimated_m.back() / travelled_counts);
  const double window_s = 2.0 * lag_s;
  std::vector<double> travelled(rolled.size(), 0.0);  // the distance rolled, trapezoidal
  for (std::size_t k = 1; k < rolled.size(); ++k)
    travelled[k] = travelled[k - 1] + 0.5 * (rolled[k] + rolled[k - 1]) * (r.t[k] - r.t[k - 1]);
  // The edges' places depend on the recording and the rolled distance alone, not on the lag
  // being fitted: kept while both stay (one cache per thread; channels run on several).
  struct EdgeCache {
    std::vector<double> t, counts, travelled;
    EdgeTimes edges;
  };
  thread_local EdgeCache cache;
  if (cache.t != r.t || cache.counts != counts || cache.travelled != travelled) {
    cache.edges = edge_times(r, counts, rolled, travelled);
    cache.t = r.t, cache.counts = counts, cache.travelled = travelled;
  }
  const std::vector<double>& edges = cache.edges.at;
  const double shift_s = cache.edges.shift_s;
  bool edge_seen = false;
  double last_edge_s = 0.0, motion_from_s = 0.0, held = 0.0;
  y.assign(rolled.size(), 0.0);
  for (std::size_t k = 0; k < y.size(); ++k) {
    if (k > 0 && counts[k] != counts[k - 1]) {
      const double edge_s = edges[k];
      const double gap_s = edge_s - last_edge_s;
      if (!edge_seen || gap_s > window_s) {
        // The motion's first edge: nothing newer to time it from, one count over the gap.
        held = edge_seen ? std::copysign(m_per_count / gap_s, rolled[k]) : 0.0;
        motion_from_s = edge_s;
      } else {
        const double span_s = std::min(window_s, edge_s - motion_from_s);
        if (span_s > 0.0)
          held = (at_time(r, travelled, edge_s - shift_s) -
                  at_time(r, travelled, edge_s - shift_s - span_s)) /
                 span_s;
      }
      edge_seen = true;
      last_edge_s = edge_s;
    }
    const double since_s = r.t[k] - last_edge_s;
    if (!edge_seen) {
      y[k] = 0.0;
    } else if (since_s > 0.0 && std::abs(held) > m_per_count / since_s) {
      y[k] = std::copysign(m_per_count / since_s, held);
    } else {
      y[k] = held;
    }
  }
}

// A recorded input's own measurement noise as the analysed rows carry it: white noise of the
// size measured at the recording's own rate (second differences, before any filter), passed
// through the same anti-alias filter and thinning as the recording (a fixed seed: the same
// figure each run). What a structure makes of it is the errors-in-variables floor of its
// residual (ChannelModel::input_noise_rms): the input's noise is not the output's to explain.
struct AnalysedNoise {
  std::vector<double> n;
  std::size_t stride = 1, rows = 0;
  double dt = 0.0;
  [[nodiscard]] double at(std::size_t row) const { return n[row * stride]; }
};
AnalysedNoise analysed_input_noise(const Recording& r, const std::string& column, std::size_t end) {
  AnalysedNoise out;
  const auto measured = r.full_rate_noise.find(column);
  const double sigma = measured != r.full_rate_noise.end()
                           ? measured->second
                           : white_noise_rms(r.at(column), std::min(end, r.size()));
  out.stride = r.decimation_stride;
  const std::size_t rows = std::min<std::size_t>(std::min(end, r.size()), 20000);
  if (rows < 9 || sigma <= 0.0) return out;
  out.rows = rows;
  out.dt = (r.t[rows - 1] - r.t[0]) / static_cast<double>(rows - 1);
  std::mt19937 rng(1);
  std::normal_distribution<double> white(0.0, sigma);
  out.n.resize(rows * out.stride);
  for (double& v : out.n) v = white(rng);
  if (out.stride > 1) {
    const double rate = static_cast<double>(out.stride) / out.dt;
    zero_phase_lowpass(out.n, anti_alias_cutoff_hz(1.0 / out.dt), rate);
  }
  return out;
}

// `always`, and a hard limit too where the output shows one: its largest value recorded
// exactly, at the recording's own rate, on 20 rows or more. A saturating sensor records its limit
// over and over; a loop that holds a force has its largest reading once, a noise peak (a limit
// there clipped the noise and named a ceiling of 89.7 N on the field's clamp).
std::vector<const EffectSpec*> with_flat_top(const Recording& r, const std::string& output,
                                             std::initializer_list<EffectKind> always) {
  std::vector<const EffectSpec*> out = specs(always);
  const auto full_rate = r.full_rate_top_rows.find(output);
  const std::size_t held =
      full_rate != r.full_rate_top_rows.end() ? full_rate->second : rows_at_top(r.at(output));
  if (held >= 20) out.push_back(&effect_spec(EffectKind::kSaturation));
  return out;
}

class GroundChannel : public ChannelModel {
 public:
  std::string subsystem() const override { return "ground"; }
  std::string output() const override { return "v_wheel"; }
  std::string law() const override { return "the soil wheel's speed estimate"; }
  std::string input() const override { return "v_ground"; }
  std::vector<std::string> needs() const override { return {"v_ground", "v_wheel"}; }
  std::vector<std::string> known_inputs() const override { return {"known_slip"}; }
  // v_wheel = v (1 - s): the prediction exceeds the record by v s.
  const DisturbanceSpec* disturbance(const Recording& r) const override {
    static const DisturbanceSpec slip{"slip of the soil wheel along the row", "%", 100.0};
    return r.has("known_slip") ? nullptr : &slip;
  }
  std::vector<double> disturbance_gain(const Recording&, const std::vector<double>&,
                                       const std::vector<double>& prediction) const override {
    return prediction;
  }
  // The ground speed sensor's noise reaches v_wheel's prediction whole where the model shifts
  // v_ground by the lag; the firmware's estimate from the counts averages the distance over a
  // window of twice the lag, which keeps dt / (2 lag) of its variance.
  double input_noise_rms(const Recording& r, const std::vector<double>& p,
                         std::size_t end) const override {
    const AnalysedNoise n = analysed_input_noise(r, "v_ground", end);
    if (n.rows < 9) return 0.0;
    double sum = 0.0;
    for (std::size_t k = 0; k < n.rows; ++k) sum += n.at(k) * n.at(k);
    double rms = std::sqrt(sum / static_cast<double>(n.rows));
    const bool from_counts = r.has("wheel_counts") && r.decimation_stride == 1 && p[0] > 0.0;
    if (from_counts) rms *= std::sqrt(std::min(1.0, n.dt / (2.0 * p[0])));
    return rms;
  }
  // The encoder speed is an estimate over a window of edges: it lags the true speed by
  // about half the window. That lag is part of the measurement, not missing physics.
  std::vector<ParamSpec> nominal_params() const override {
    return {{"estimator_lag_s", "s", 0.1, 0.0, 1.0}};
  }
  std::vector<const EffectSpec*> candidates(const Recording& r) const override {
    return specs(r, {EffectKind::kWheelRadius, EffectKind::kOffset, EffectKind::kQuantisation},
                 "depth_force", EffectKind::kSlipWithDraft);
  }
  void simulate(const Recording& r, const std::vector<double>& p, const std::vector<Effect>& fx,
                std::vector<double>& y) const override {
    std::vector<double> rolled = r.at("v_ground");
    if (r.has("known_slip")) {
      // The wheel rolls the ground less its slip: v_wheel = v (1 - s).
      const auto& slip = r.at("known_slip");
      for (std::size_t k = 0; k < rolled.size(); ++k) rolled[k] *= 1.0 - slip[k];
    }
    as_estimated(r, rolled, p[0], y);
    apply_output(r, fx, r.has("depth_force") ? &r.at("depth_force") : nullptr, nullptr, y);
  }
};

class DiscSpeedChannel : public ChannelModel {
 public:
  std::string subsystem() const override { return "disc drive"; }
  std::string output() const override { return "omega"; }
  std::string law() const override { return "the disc drive's speed loop"; }
  std::string input() const override { return "omega_cmd"; }
  std::vector<std::string> needs() const override { return {"omega_cmd", "omega"}; }
  std::vector<ParamSpec> nominal_params() const override {
    return {{"T_d", "s", 0.1, 0.005, 5.0}, {"omega_max", "rad/s", 2.0, 0.01, 50.0}};
  }
  std::vector<double> initial_guess(const Recording& r) const override {
    double m = 0;
    for (double v : r.at("omega")) m = std::max(m, std::abs(v));
    return {0.1, std::max(0.02, 1.5 * m)};
  }
  std::vector<const EffectSpec*> candidates(const Recording&) const override {
    return specs({EffectKind::kDelay, EffectKind::kBacklash, EffectKind::kBacklashOutput,
                  EffectKind::kDeadZone, EffectKind::kLoopFriction, EffectKind::kRateLimit,
                  EffectKind::kGain, EffectKind::kOffset, EffectKind::kPeriodic});
  }
  void simulate(const Recording& r, const std::vector<double>& p, const std::vector<Effect>& fx,
                std::vector<double>& y) const override {
    const std::vector<double> u = transform_input(r, command_at_drive(r, r.at("omega_cmd")), fx);
    lag(r, u, p[0], p[1], fx, r.at("omega")[0], y);
    apply_output(r, fx, nullptr, nullptr, y);
  }
};

class DiscTorqueChannel : public ChannelModel {
 public:
  std::string subsystem() const override { return "disc drive"; }
  std::string output() const override { return "disc_torque"; }
  std::string law() const override { return "the disc's inertia and damping"; }
  std::string input() const override { return "omega"; }
  std::vector<std::string> needs() const override { return {"omega", "disc_torque"}; }
  std::vector<ParamSpec> nominal_params() const override {
    return {{"J", "kg m^2", 0.1, 0.0, 1e3}, {"b", "N m s/rad", 1.0, -1e3, 1e3}};
  }
  // Stiction needs the speed command (the drive's effort while the disc is held).
  std::vector<const EffectSpec*> candidates(const Recording& r) const override {
    std::vector<const EffectSpec*> out =
        with_flat_top(r, output(),
                      {EffectKind::kCoulomb, EffectKind::kStribeck, EffectKind::kOffset,
                       EffectKind::kPeriodic, EffectKind::kDelay});
    if (r.has("omega_cmd")) out.push_back(&effect_spec(EffectKind::kStiction));
    return out;
  }
  // At one steady speed the viscous term b omega is a constant: an offset trades with it unless
  // the disc is also recorded at rest.
  std::optional<std::size_t> zero_load_rows(const Recording& r, const std::vector<double>& p,
                                            std::size_t end) const override {
    return rows_at_zero_load(*this, r, p, end);
  }
  // The torque is computed from the measured speed: its noise n enters as
  // J (n[k+1] - n[k-1]) / (t[k+1] - t[k-1]) + b n[k] (a heavy disc on a quick drive makes this
  // several times the torque sensor's own noise). The speed's noise is measured at the
  // recording's own rate; white noise of that size is passed through the same anti-alias filter
  // and thinning as the recording, then through that map (a fixed seed: the same figure each run).
  double input_noise_rms(const Recording& r, const std::vector<double>& p,
                         std::size_t end) const override {
    const AnalysedNoise n = analysed_input_noise(r, "omega", end);
    if (n.rows < 9) return 0.0;
    double sum = 0.0;
    for (std::size_t k = 1; k + 1 < n.rows; ++k) {
      const double e = p[0] * (n.at(k + 1) - n.at(k - 1)) / (2.0 * n.dt) + p[1] * n.at(k);
      sum += e * e;
    }
    return std::sqrt(sum / static_cast<double>(n.rows - 2));
  }
  // d(omega)/dt by central differences over +-kHalf samples: wider windows smear the fast
  // torque transients of a drive whose loop is quicker than the thinned sampling.
  static constexpr std::size_t kHalf = 1;
  std::size_t rows_ahead() const override { return kHalf; }
  void simulate(const Recording& r, const std::vector<double>& p, const std::vector<Effect>& fx,
                std::vector<double>& y) const override {
    const std::vector<double> w = transform_input(r, r.at("omega"), fx);
    const std::size_t n = w.size();
    y.assign(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t a = k >= kHalf ? k - kHalf : 0, b = std::min(n - 1, k + kHalf);
      const double dw = b > a ? (w[b] - w[a]) / (r.t[b] - r.t[a]) : 0.0;
      y[k] = p[0] * dw + p[1] * w[k];
    }
    apply_output(r, fx, nullptr, &w, y);
    if (const Effect* st = find_effect(fx, EffectKind::kStiction); st && r.has("omega_cmd")) {
      const auto& cmd = r.at("omega_cmd");
      for (std::size_t k = 0; k < n; ++k) {
        if (std::abs(w[k]) < 1e-3 && std::abs(cmd[k]) > 1e-3)
          y[k] = std::clamp(st->values[0] * cmd[k], -st->values[1], st->values[1]);
      }
    }
  }
};

// Where the recorded clamp force peaks, and the roller's lowest position: the clamp law's
// starts pass k through the peak for a given contact point x0 and exponent n.
struct ClampPeak {
  double at_mm = 0.0, force_N = 0.0, lowest_mm = 0.0;
  [[nodiscard]] std::vector<double> start(double x0, double n) const {
    return {std::max(1e-3, force_N / std::pow(std::max(0.1, at_mm - x0), n)), x0, n};
  }
};

ClampPeak clamp_peak(const Recording& r) {
  const auto& x = r.at("clamp_pos_mm");
  const auto& f = r.at("clamp_force");
  ClampPeak peak;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (f[k] > peak.force_N) peak.force_N = f[k], peak.at_mm = x[k];
  peak.lowest_mm = *std::min_element(x.begin(), x.end());
  return peak;
}

// (x - x0)^n over a recording, as exp(n ln(x - x0)) (the general pow() is twice as slow for
// the same result here: x - x0 > 0, n in 0.9-2.5), 0 where x <= x0. The fits call it millions
// of times, and a numeric Jacobian moves one parameter at a time from a base point and back:
// the logarithms are kept for the last two x0 and the powers for the last four (x0, n) while x
// stays, so that a step in k, in n or in an effect's parameter reuses the base point's. One
// cache per thread: channels are analysed on several.
const std::vector<double>& law_power(const std::vector<double>& x, double x0, double n) {
  struct Logs {
    double x0 = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> log_d;
  };
  struct Powers {
    double x0 = std::numeric_limits<double>::quiet_NaN(), n = x0;
    std::vector<double> power;
    std::uint64_t used = 0;
  };
  struct Cache {
    std::vector<double> x;
    std::array<Logs, 2> logs;
    std::array<Powers, 4> powers;
    std::uint64_t clock = 0;
  };
  thread_local Cache c;
  if (!same_bits(x, c.x)) {
    c.x = x;
    for (auto& l : c.logs) l.x0 = std::numeric_limits<double>::quiet_NaN();
    for (auto& p : c.powers) p.x0 = std::numeric_limits<double>::quiet_NaN();
  }
  ++c.clock;
  for (auto& p : c.powers)
    if (p.x0 == x0 && p.n == n) return p.used = c.clock, p.power;
  const std::vector<double>& log_d =
      recent_two(
          c.logs, [&](const Logs& l) { return l.x0 == x0; },
          [&](Logs& fresh) {
            fresh.x0 = x0;
            fresh.log_d.resize(x.size());
            for (std::size_t k = 0; k < x.size(); ++k) {
              const double d = x[k] - x0;
              fresh.log_d[k] = d > 0.0 ? std::log(d) : -std::numeric_limits<double>::infinity();
            }
          })
          .log_d;
  Powers& p = *std::min_element(c.powers.begin(), c.powers.end(),
                                [](const Powers& a, const Powers& b) { return a.used < b.used; });
  p.x0 = x0, p.n = n, p.used = c.clock;
  p.power.resize(x.size());
  // exp(n * -inf) is 0 for n > 0: the open clamp.
  for (std::size_t k = 0; k < x.size(); ++k) p.power[k] = std::exp(n * log_d[k]);
  return p.power;
}

class ClampChannel : public ChannelModel {
 public:
  std::string subsystem() const override { return "clamp"; }
  std::string output() const override { return "clamp_force"; }
  std::string law() const override { return "the clamp law"; }
  std::string input() const override { return "clamp_pos_mm"; }
  std::string displacement() const override { return "clamp_pos_mm"; }
  std::vector<std::string> needs() const override { return {"clamp_pos_mm", "clamp_force"}; }
  std::vector<std::string> known_inputs() const override { return {"known_nip_mm"}; }
  // A stem of thickness d in the nip moves the law's contact by d: the record exceeds the
  // prediction by dF/dx d = k n (x - x0)^(n-1) d.
  const DisturbanceSpec* disturbance(const Recording& r) const override {
    static const DisturbanceSpec stems{"stems' spread in the nip", "mm", 1.0};
    return r.has("known_nip_mm") ? nullptr : &stems;
  }
  // The machine counted seedlings (its photo-eye, at release): stems went through the nip. A
  // recording without the count, or with none planted, may hold no stem at all.
  bool disturbance_shown(const Recording& r) const override {
    if (!r.has("seedlings") || r.at("seedlings").empty()) return false;
    const std::vector<double>& count = r.at("seedlings");
    const auto [lo, hi] = std::minmax_element(count.begin(), count.end());
    return *hi - *lo >= 1.0;
  }
  std::vector<double> disturbance_gain(const Recording& r, const std::vector<double>& p,
                                       const std::vector<double>&) const override {
    const auto& x = r.at("clamp_pos_mm");
    std::vector<double> g(x.size(), 0.0);
    for (std::size_t k = 0; k < x.size(); ++k)
      if (x[k] > p[1]) g[k] = -p[0] * p[2] * std::pow(x[k] - p[1], p[2] - 1.0);
    return g;
  }
  std::vector<ParamSpec> nominal_params() const override {
    return {{"k_c", "N/mm^n", 10.0, 1e-3, 1e5},
            {"x0", "mm", 0.0, -50.0, 50.0},
            {"n", "1", 1.2, 0.9, 2.5}};
  }
  std::vector<double> initial_guess(const Recording& r) const override {
    const ClampPeak peak = clamp_peak(r);
    return peak.start(peak.lowest_mm, 1.2);
  }
  // The law's exponent over its range, each with the contact point at the smallest position
  // and at a third of the stroke, and k through the largest force: k, x0 and n trade, and a
  // fit from one start alone can stop in a valley with n far from the truth (issue 32).
  std::vector<std::vector<double>> nominal_starts(const Recording& r) const override {
    const ClampPeak peak = clamp_peak(r);
    const double lo = peak.lowest_mm;
    std::vector<std::vector<double>> out;
    for (double n : {1.0, 1.6, 2.2}) {
      for (double x0 : {lo, lo + (peak.at_mm - lo) / 3.0}) out.push_back(peak.start(x0, n));
    }
    return out;
  }
  // The roller short of the contact point fitted beside the offset: no seedling is squeezed
  // there, the force sensor reads its offset alone.
  std::optional<std::size_t> zero_load_rows(const Recording& r, const std::vector<double>& p,
                                            std::size_t end) const override {
    return rows_at_zero_load(*this, r, p, end);
  }
  // n within 0.9-2.5: the format gives 1-1.5 from the DEM; a law much softer than linear
  // would be the fit bending to mimic creep. A sensor gain error is the same as a different
  // k_c: the nominal fit absorbs it.
  std::vector<const EffectSpec*> candidates(const Recording& r) const override {
    return with_flat_top(r, output(),
                         {EffectKind::kOffset, EffectKind::kDrift, EffectKind::kRelaxation,
                          EffectKind::kRelaxation2, EffectKind::kHysteresis, EffectKind::kBacklash,
                          EffectKind::kPeriodic, EffectKind::kQuantisation, EffectKind::kDelay});
  }
  void simulate(const Recording& r, const std::vector<double>& p, const std::vector<Effect>& fx,
                std::vector<double>& y) const override {
    std::vector<double> x = transform_input(r, r.at("clamp_pos_mm"), fx);
    // A seedling in the nip closes the gap by its thickness: the lips meet it sooner.
    if (r.has("known_nip_mm")) {
      const auto& nip = r.at("known_nip_mm");
      for (std::size_t k = 0; k < x.size(); ++k) x[k] += nip[k];
    }
    const std::vector<double>& power = law_power(x, p[1], p[2]);
    y.resize(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) y[k] = p[0] * power[k];
    apply_output(r, fx, nullptr, nullptr, y, displacement());
  }
};

class DepthChannel : public ChannelModel {
 public:
  std::string subsystem() const override { return "depth"; }
  std::string output() const override { return "depth_mm"; }
  std::string law() const override { return "the depth actuator's lag"; }
  std::string input() const override { return "depth_cmd_mm"; }
  std::vector<std::string> needs() const override { return {"depth_cmd_mm", "depth_mm"}; }
  std::vector<std::string> known_inputs() const override { return {"known_terrain_depth_mm"}; }
  // The terrain adds to the furrow's depth as recorded: the record exceeds the prediction by it.
  const DisturbanceSpec* disturbance(const Recording& r) const override {
    static const DisturbanceSpec terrain{"terrain under the depth wheel", "mm", 1.0};
    return r.has("known_terrain_depth_mm") ? nullptr : &terrain;
  }
  std::vector<double> disturbance_gain(const Recording& r, const std::vector<double>&,
                                       const std::vector<double>&) const override {
    return std::vector<double>(r.size(), -1.0);
  }
  std::vector<ParamSpec> nominal_params() const override {
    return {{"T_a", "s", 0.5, 0.01, 20.0}, {"r_max", "mm/s", 50.0, 0.1, 2000.0}};
  }
  std::vector<const EffectSpec*> candidates(const Recording& r) const override {
    return specs(r,
                 {EffectKind::kDelay, EffectKind::kDeadZone, EffectKind::kBacklash,
                  EffectKind::kBacklashOutput, EffectKind::kOffset, EffectKind::kGain,
                  EffectKind::kPeriodic},
                 "depth_force", EffectKind::kSag);
  }
  void simulate(const Recording& r, const std::vector<double>& p, const std::vector<Effect>& fx,
                std::vector<double>& y) const override {
    const std::vector<double> u = transform_input(r, command_at_drive(r, r.at("depth_cmd_mm")), fx);
    // The nominal rate limit r_max is part of the structure; a candidate one would repeat it.
    const double tau = p[0], rate = p[1];
    // The furrow's depth is the actuator's position plus what the terrain adds, where known.
    const std::vector<double>* terrain =
        r.has("known_terrain_depth_mm") ? &r.at("known_terrain_depth_mm") : nullptr;
    double state = r.at("depth_mm")[0] - (terrain ? (*terrain)[0] : 0.0);
    y.assign(u.size(), r.at("depth_mm")[0]);
    // The lag's step response once per distinct step: the rows are evenly sampled, and the fits
    // run this millions of times.
    double lag_dt = -1.0, lag_share = 0.0;
    for (std::size_t k = 1; k < u.size(); ++k) {
      const double dt = r.t[k] - r.t[k - 1];
      if (dt != lag_dt) lag_dt = dt, lag_share = 1.0 - std::exp(-dt / tau);
      const double step = lag_share * (u[k - 1] - state);
      state += std::clamp(step, -rate * dt, rate * dt);
      y[k] = state + (terrain ? (*terrain)[k] : 0.0);
    }
    apply_output(r, fx, r.has("depth_force") ? &r.at("depth_force") : nullptr, nullptr, y);
  }
};

// Soil draft on the opener in ASABE D497's form, mobilised over travel and relaxing at rest
// (sim/soil/opener_draft.h, where the sources are cited). A recording holds one or two forward
// speeds, so B and C cannot be told from A: they are held at the standard row's ratios to A. The
// fit finds the draft at the reference depth, the depth exponent m, the mobilisation travel K and
// the relaxation time tau. The speed column and the force sensor need not be sampled together
// (planter-sim writes the true speed at the tick and the force as the controller received it,
// 20 ms later): their relative lag is a nominal parameter, as the soil wheel's is.

// Where the machine stands (at_rest.h): from the column the analysis carries when the
// recording was thinned, found at the full rate before the anti-alias filter; otherwise from
// this recording's own wheel speed.
std::vector<bool> standing(const Recording& r) {
  if (r.has(kAtRestColumn)) {
    const std::vector<double>& column = r.at(kAtRestColumn);
    std::vector<bool> out(column.size());
    for (std::size_t k = 0; k < column.size(); ++k) out[k] = column[k] != 0.0;
    return out;
  }
  return wheel_at_rest(r);
}

class DraftChannel : public ChannelModel {
 public:
  std::string subsystem() const override { return "depth"; }
  std::string output() const override { return "depth_force"; }
  std::string law() const override { return "the draft law"; }
  std::string input() const override { return "depth_mm"; }
  std::vector<std::string> needs() const override { return {"depth_mm", "depth_force", "v_wheel"}; }
  std::vector<ParamSpec> nominal_params() const override {
    const soil::OpenerDraftLaw row;
    return {{"draft_100mm", "N", 500.0, 0.0, 1e5},
            // Ranges to the limits the physics allows (issue 32): the depth exponent either
            // side of D497's linear 1 (assumed 0.5-3), a draft mobilised and released
            // within one row (10 um, 10 ms) up to a metre and an hour.
            {"m", "1", 1.5, 0.5, 3.0},
            {"speed_lag_s", "s", 0.02, 0.0, 0.5},
            {"mobilisation_mm", "mm", row.mobilisation_mm, 0.01, 1000.0},
            {"rest_relaxation_s", "s", row.rest_relaxation_s, 0.01, 3600.0}};
  }
  std::vector<const EffectSpec*> candidates(const Recording& r) const override {
    return with_flat_top(r, output(),
                         {EffectKind::kOffset, EffectKind::kPeriodic, EffectKind::kDelay,
                          EffectKind::kQuantisation});
  }
  // The mobilisation travel and the relaxation time trade against each other and against the
  // draft's size (at a steady speed only K / (v tau) shows): starts a decade either side of
  // the standard row's, so that no effect takes credit for a valley the nominal did not reach.
  std::vector<std::vector<double>> nominal_starts(const Recording& r) const override {
    const std::vector<double> guess = initial_guess(r);
    std::vector<std::vector<double>> out;
    for (const auto& [k_factor, tau_factor] :
         {std::pair{1.0, 0.1}, std::pair{1.0, 10.0}, std::pair{0.1, 1.0}, std::pair{10.0, 1.0}}) {
      std::vector<double> start = guess;
      start[3] *= k_factor;
      start[4] *= tau_factor;
      out.push_back(start);
    }
    return out;
  }
  // At one depth and speed the draft is a constant: an offset trades with draft_100mm unless the
  // recording holds the draft released at rest (or the opener raised).
  std::optional<std::size_t> zero_load_rows(const Recording& r, const std::vector<double>& p,
                                            std::size_t end) const override {
    return rows_at_zero_load(*this, r, p, end);
  }
  void simulate(const Recording& r, const std::vector<double>& p, const std::vector<Effect>& fx,
                std::vector<double>& y) const override {
    const std::vector<double> d = transform_input(r, r.at("depth_mm"), fx);
    const Effect lag{&effect_spec(EffectKind::kDelay), {p[2]}};
    const std::vector<double> v =
        transform_input(r, r.has("v_ground") ? r.at("v_ground") : r.at("v_wheel"), {lag});
    const std::vector<bool> rest = standing(r);
    // The default row, scaled so that F_i A T_ref is the fitted draft at the reference depth.
    const soil::OpenerDraftLaw row;
    soil::OpenerDraftLaw law = row;
    const double scale = p[0] / (0.1 * soil::kDraftReferenceDepth_mm * row.a_N_per_cm);
    law.texture_factor = 1.0;
    law.a_N_per_cm = row.a_N_per_cm * scale;
    law.b_N_per_cm_kmh = row.b_N_per_cm_kmh * scale;
    law.c_N_per_cm_kmh2 = row.c_N_per_cm_kmh2 * scale;
    law.depth_exponent = p[1];
    law.mobilisation_mm = p[3];
    law.rest_relaxation_s = p[4];
    const std::vector<double>& share =
        draft_share_along(law.mobilisation_mm, law.rest_relaxation_s, v, rest, r.t);
    const std::vector<double>& depth_cm = draft_depth_along(d, law.depth_exponent);
    y.resize(d.size());
    for (std::size_t k = 0; k < d.size(); ++k) {
      const double v_k = rest[k] ? 0.0 : v[k];
      y[k] = law.texture_factor * soil::draft_per_cm_N(law, v_k) * depth_cm[k] * share[k];
    }
    apply_output(r, fx, nullptr, nullptr, y);
  }
};

}  // namespace

std::vector<double> ChannelModel::initial_guess(const Recording&) const {
  std::vector<double> out;
  for (const auto& p : nominal_params()) out.push_back(p.initial);
  return out;
}

std::vector<double> distance_travelled(const Recording& r) {
  std::vector<double> s(r.size(), 0.0);
  const char* column = r.has("v_ground") ? "v_ground" : r.has("v_wheel") ? "v_wheel" : nullptr;
  if (column == nullptr) return s;
  const auto& v = r.at(column);
  for (std::size_t k = 1; k < s.size(); ++k)
    s[k] = s[k - 1] + 0.5 * (std::abs(v[k]) + std::abs(v[k - 1])) * (r.t[k] - r.t[k - 1]);
  return s;
}

std::size_t rows_at_zero_load(const ChannelModel& ch, const Recording& r,
                              const std::vector<double>& nominal, std::size_t end) {
  std::vector<double> y;
  ch.simulate(r, nominal, {}, y);
  double size = 0.0;
  for (double v : r.at(ch.output())) size = std::max(size, std::abs(v));
  std::size_t n = 0;
  for (std::size_t k = 0; k < std::min(end, y.size()); ++k) n += std::abs(y[k]) <= 0.01 * size;
  return n;
}

std::vector<const ChannelModel*> all_channels() {
  static const GroundChannel ground;
  static const DiscSpeedChannel disc;
  static const DiscTorqueChannel torque;
  static const ClampChannel clamp;
  static const DepthChannel depth;
  static const DraftChannel draft;
  return {&ground, &disc, &torque, &clamp, &depth, &draft};
}

}  // namespace planter::analysis
