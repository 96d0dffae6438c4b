#include "analysis/change_points.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "analysis/residual_stats.h"

namespace planter::analysis {
namespace {

struct Side {
  ChannelFit fit;
  double rss = 0.0;
};

// The model refitted on the calibration rows before `at` and on those from it.
std::pair<Side, Side> split_at(const ChannelModel& ch, const Recording& r, const Split& split,
                               const ChannelFit& fit, std::size_t at) {
  Split before = split, after = split;
  before.fold_from = at;
  before.fold_to = split.calibration_end;
  after.fold_from = 0;
  after.fold_to = at;
  Side b, a;
  b.fit = refit(ch, r, before, fit, &b.rss);
  a.fit = refit(ch, r, after, fit, &a.rss);
  return {b, a};
}

double rss_between(const ChannelModel& ch, const Recording& r, const ChannelFit& f,
                   std::size_t from, std::size_t to) {
  std::vector<double> pred;
  ch.simulate(r, f.nominal, f.effects, pred);
  const std::vector<double>& y = r.at(ch.output());
  double s = 0;
  for (std::size_t k = from; k < to; ++k) s += (pred[k] - y[k]) * (pred[k] - y[k]);
  return s;
}

// The one parameter that, changed alone from the values before the switch, best fits the part
// after it: a golden-section search on each in turn. Returns its index and value, and the share
// of the all-parameter change's gain it reaches.
struct Single {
  std::size_t index = 0;
  double value = 0.0, sd = 0.0, rss = 0.0, share = 0.0;
};
// Every parameter changed alone, best fit first.
std::vector<Single> single_changes(const ChannelModel& ch, const Recording& r,
                                   const ChannelFit& before, std::size_t from, std::size_t to,
                                   double rss_all) {
  std::vector<Single> out;
  ChannelFit trial = before;
  ParameterLayout lay = fitted_layout(ch, trial);
  bounds_for_output(lay.specs, r.at(ch.output()));
  const std::vector<double*>& p = lay.slots;
  const std::vector<ParamSpec>& specs = lay.specs;
  const double rss_none = rss_between(ch, r, trial, from, to);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double keep = *p[i];
    const double reach = std::max(std::abs(keep), 1e-3 * (specs[i].upper - specs[i].lower));
    double lo = std::max(specs[i].lower, keep - 2.0 * reach);
    double hi = std::min(specs[i].upper, keep + 2.0 * reach);
    auto f = [&](double v) {
      *p[i] = v;
      return rss_between(ch, r, trial, from, to);
    };
    for (int it = 0; it < 50; ++it) {
      const double m1 = lo + 0.382 * (hi - lo), m2 = lo + 0.618 * (hi - lo);
      if (f(m1) < f(m2))
        hi = m2;
      else
        lo = m1;
    }
    Single one;
    one.index = i;
    one.value = 0.5 * (lo + hi);
    one.rss = f(one.value);
    one.share = rss_none > rss_all ? (rss_none - one.rss) / (rss_none - rss_all) : 0.0;
    // Its standard deviation from the curvature of the RSS: sd^2 = 2 s^2 / RSS''.
    const double h = std::max(1e-6, 1e-3 * std::abs(one.value));
    const double curvature = (f(one.value + h) - 2.0 * one.rss + f(one.value - h)) / (h * h);
    const double s2 = one.rss / static_cast<double>(std::max<std::size_t>(1, to - from - 1));
    one.sd = curvature > 0 ? std::sqrt(2.0 * s2 / curvature) : 0.0;
    *p[i] = keep;
    out.push_back(one);
  }
  std::sort(out.begin(), out.end(), [](const Single& a, const Single& b) { return a.rss < b.rss; });
  return out;
}

}  // namespace

std::optional<ChangePoint> find_change_point(const ChannelModel& ch, const Recording& r,
                                             const Split& split, const ChannelFit& fit,
                                             double noise_rms) {
  const std::size_t end = split.calibration_end;
  if (end < 200) return std::nullopt;
  const double n = static_cast<double>(fitted_rows(split));
  std::map<std::size_t, double> bic;  // by switch row
  auto score = [&](std::size_t at) {
    if (bic.count(at)) return bic[at];
    const auto [b, a] = split_at(ch, r, split, fit, at);
    // Twice the parameters, and the switch time.
    const double value = n * std::log(std::max(b.rss + a.rss, 1e-300) / n) +
                         (2.0 * fit.parameters + 1.0) * std::log(n);
    return bic[at] = value;
  };
  // Coarse: every 4 % of the calibration part from 10 % to 90 %; then every 1 % around the best.
  std::size_t best = end / 10;
  for (int q = 10; q <= 90; q += 4) {
    const std::size_t at = end * static_cast<std::size_t>(q) / 100;
    if (score(at) < score(best)) best = at;
  }
  const std::size_t coarse = best;
  for (int d = -3; d <= 3; ++d) {
    const long at = static_cast<long>(coarse) + d * static_cast<long>(end) / 100;
    if (at < static_cast<long>(end / 10) || at > static_cast<long>(end * 9 / 10)) continue;
    if (score(static_cast<std::size_t>(at)) < score(best)) best = static_cast<std::size_t>(at);
  }
  ChangePoint cp;
  cp.at_s = r.t[best];
  cp.delta_bic = score(best) - fit.bic;
  // The switch times within one unit of BIC of the best (a likelihood interval of about one
  // standard deviation), at least the search's own step.
  double lo = cp.at_s, hi = cp.at_s;
  for (const auto& [at, value] : bic)
    if (value - score(best) < 1.0) lo = std::min(lo, r.t[at]), hi = std::max(hi, r.t[at]);
  const double step_s = r.t[end / 100 + 1] - r.t[1];
  cp.at_sd_s = std::max(0.5 * (hi - lo), 0.5 * step_s);
  auto [b, a] = split_at(ch, r, split, fit, best);
  cp.before = std::move(b.fit);
  cp.after = std::move(a.fit);
  // One parameter alone, when it reaches 90 % of what changing them all gains: the simpler
  // account, and the one that names what changed. (Correlated parameters, such as a clamp law's
  // stiffness and exponent, would otherwise share the change and none of them stand out.)
  // Others that account for the change as well are listed after it as ties: their shares of
  // the gain within 5 % (the rule an effect must clear over a simpler one), and what they leave
  // beyond the noise at most twice what it leaves. (Near one operating point a clamp's stiffness
  // and its contact point cannot be told apart; over a range of positions they can.)
  const std::vector<Single> singles =
      single_changes(ch, r, cp.before, best, end, rss_between(ch, r, cp.after, best, end));
  if (!singles.empty() && singles[0].share >= 0.9) {
    const Single& one = singles[0];
    ChannelFit after = cp.before;
    *fitted_layout(ch, after).slots[one.index] = one.value;
    const std::vector<FittedValue> nb = fitted_values(ch, cp.before);
    const double rss_noise = noise_rms * noise_rms * static_cast<double>(end - best);
    const double left = std::max(one.rss - rss_noise, 0.1 * rss_noise);
    for (const Single& s : singles)
      if (s.share >= 0.9 && s.share > one.share - 0.05 && s.rss - rss_noise <= 2.0 * left)
        cp.changed.push_back(
            {nb[s.index].name, nb[s.index].unit, nb[s.index].value, nb[s.index].sd, s.value, s.sd});
    cp.tied = cp.changed.size() > 1;
    ch.simulate(r, after.nominal, after.effects, after.prediction);
    cp.after = std::move(after);
  }
  const std::vector<double>& y = r.at(ch.output());
  cp.prediction = cp.before.prediction;
  for (std::size_t k = best; k < y.size(); ++k) cp.prediction[k] = cp.after.prediction[k];
  cp.rms_calibration = rms_between(cp.prediction, y, 0, end);
  cp.rms_held_out = rms_between(cp.prediction, y, end, y.size());
  if (!cp.changed.empty()) return cp;
  // Otherwise the parameters that moved: by more than five standard deviations of the
  // difference and by more than 5 % of their size.
  const std::vector<FittedValue> nb = fitted_values(ch, cp.before),
                                 na = fitted_values(ch, cp.after);
  std::vector<std::pair<double, ParameterChange>> moved;
  for (std::size_t k = 0; k < nb.size() && k < na.size(); ++k) {
    const double diff = std::abs(na[k].value - nb[k].value);
    const double sd = std::hypot(nb[k].sd, na[k].sd);
    const double size = std::max(std::abs(na[k].value), std::abs(nb[k].value));
    if (diff > 5.0 * sd && diff > 0.05 * size)
      moved.push_back({diff / std::max(size, 1e-300),
                       {nb[k].name, nb[k].unit, nb[k].value, nb[k].sd, na[k].value, na[k].sd}});
  }
  std::sort(moved.begin(), moved.end(),
            [](const auto& x, const auto& z) { return x.first > z.first; });
  for (auto& m : moved) cp.changed.push_back(std::move(m.second));
  return cp;
}

}  // namespace planter::analysis
