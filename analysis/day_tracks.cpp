#include "analysis/day_tracks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <thread>

#include "analysis/glitches.h"

namespace planter::analysis {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// One window's refit of a channel's final model: all its rows calibrate, none is held out.
std::vector<FittedValue> refit_window(const ChannelModel& ch, const Recording& w,
                                      const ChannelFit& model) {
  ChannelFit start = model;
  ch.simulate(w, start.nominal, start.effects, start.prediction);
  const ChannelFit f = refit(ch, w, Split{w.size(), 0, 0}, start);
  return fitted_values(ch, f);
}

std::string format_hours(double s) {
  std::ostringstream o;
  o.precision(3);
  o << s / 3600.0 << " h";
  return o.str();
}

}  // namespace

void judge_track(Track& tr) {
  const std::size_t n = tr.value.size();
  if (n < 4) {
    tr.verdict = "too few windows";
    return;
  }
  const double w = static_cast<double>(n);
  double mean = 0;
  for (double v : tr.value) mean += v / w;
  // The track's own noise: window-to-window differences (robust to one step), never below the
  // median of the refits' standard deviations.
  std::vector<double> diffs;
  for (std::size_t k = 1; k < n; ++k) diffs.push_back(std::abs(tr.value[k] - tr.value[k - 1]));
  const double sigma = std::max({1.4826 * median(diffs) / std::sqrt(2.0), median(tr.sd),
                                 1e-9 * std::max(1.0, std::abs(mean))});
  auto chi2 = [&](auto model) {
    double s = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double e = (tr.value[k] - model(k)) / sigma;
      s += e * e;
    }
    return s;
  };
  const double bic_constant = chi2([&](std::size_t) { return mean; }) + std::log(w);
  // A line in time.
  double st = 0, sv = 0, stt = 0, stv = 0;
  for (std::size_t k = 0; k < n; ++k) {
    st += tr.t_s[k];
    sv += tr.value[k];
    stt += tr.t_s[k] * tr.t_s[k];
    stv += tr.t_s[k] * tr.value[k];
  }
  const double slope = (w * stv - st * sv) / std::max(1e-300, w * stt - st * st);
  const double icpt = (sv - slope * st) / w;
  const double bic_line =
      chi2([&](std::size_t k) { return icpt + slope * tr.t_s[k]; }) + 2.0 * std::log(w);
  // One step, each side at least two windows.
  double best_step = 1e300, lo_mean = 0, hi_mean = 0;
  std::size_t best_k = 0;
  std::vector<double> step_chi2(n, 1e300);
  for (std::size_t k = 2; k + 2 <= n; ++k) {
    double a = 0, b = 0;
    for (std::size_t j = 0; j < k; ++j) a += tr.value[j] / static_cast<double>(k);
    for (std::size_t j = k; j < n; ++j) b += tr.value[j] / static_cast<double>(n - k);
    step_chi2[k] = chi2([&](std::size_t j) { return j < k ? a : b; });
    if (step_chi2[k] < best_step) best_step = step_chi2[k], best_k = k, lo_mean = a, hi_mean = b;
  }
  const double bic_step = best_step + 3.0 * std::log(w);
  const double level = std::max(std::abs(mean), 1e-12);
  const double span_s = tr.t_s.back() - tr.t_s.front();
  const bool step_matters = best_k > 0 && std::abs(hi_mean - lo_mean) > 0.05 * level &&
                            std::abs(hi_mean - lo_mean) > 5.0 * sigma;
  const bool drift_matters =
      std::abs(slope * span_s) > 0.05 * level && std::abs(slope * span_s) > 5.0 * sigma;
  // A clear margin (10, "very strong") over the constant, and over each other.
  if (step_matters && bic_step < bic_constant - 10.0 && bic_step <= bic_line) {
    tr.verdict = "changed";
    // Between the last window before and the first after; +- over the switch positions whose
    // chi-square is within one of the best.
    tr.at_s = 0.5 * (tr.t_s[best_k - 1] + tr.t_s[best_k]);
    double lo = tr.at_s, hi = tr.at_s;
    for (std::size_t k = 2; k + 2 <= n; ++k)
      if (step_chi2[k] - best_step < 1.0) {
        const double at = 0.5 * (tr.t_s[k - 1] + tr.t_s[k]);
        lo = std::min(lo, at);
        hi = std::max(hi, at);
      }
    const double half_window = 0.5 * (tr.t_s[1] - tr.t_s[0]);
    tr.at_sd_s = std::max(0.5 * (hi - lo), half_window);
    tr.before = lo_mean;
    tr.after = hi_mean;
  } else if (drift_matters && bic_line < bic_constant - 10.0) {
    tr.verdict = "drifting";
    tr.slope_per_h = slope * 3600.0;
  } else {
    tr.verdict = "stable";
  }
}

DayReport track_day(RecordingReader& reader, const Recording& first, const FitReport& rep,
                    const FitOptions& o) {
  DayReport day;
  day.channels.resize(rep.channels.size());
  for (std::size_t c = 0; c < rep.channels.size(); ++c)
    for (const FittedValue& v : fitted_values(*rep.channels[c].channel, rep.channels[c].final_fit))
      day.channels[c].tracks.push_back({v.name, v.unit, {}, {}, {}, "", 0, 0, 0, 0, 0});
  day.window_s = first.t.back() - first.t.front();
  day.rows = first.size();
  const std::vector<std::string> columns = channel_columns();
  reader.keep_only(columns);
  auto add_window = [&](const Recording& w) {
    // A last piece shorter than a quarter window is too short to refit: counted, not tracked.
    if (w.size() < first.size() / 4 || w.size() < 50) {
      day.untracked_rows += w.size();
      return;
    }
    const Recording a = analysed_recording(w, o, find_glitches(w, columns));
    const double middle = 0.5 * (a.t.front() + a.t.back());
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
      for (std::size_t c = next++; c < rep.channels.size(); c = next++) {
        const ChannelModel& ch = *rep.channels[c].channel;
        // A window where the output never moves says nothing about its physics.
        if (!a.has(ch.output()) || signal_span(a.at(ch.output())) <= 0.0) continue;
        const std::vector<FittedValue> v = refit_window(ch, a, rep.channels[c].final_fit);
        for (std::size_t k = 0; k < v.size() && k < day.channels[c].tracks.size(); ++k) {
          Track& tr = day.channels[c].tracks[k];
          tr.t_s.push_back(middle);
          tr.value.push_back(v[k].value);
          tr.sd.push_back(v[k].sd);
        }
      }
    };
    std::vector<std::thread> pool;
    for (int j = 1; j < std::min<int>(o.jobs, static_cast<int>(rep.channels.size())); ++j)
      pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    ++day.windows;
  };
  add_window(first);
  double last_t = first.t.back();
  Recording w;
  while (reader.read(w, first.size()) > 0) {
    day.rows += w.size();
    last_t = w.t.back();
    add_window(w);
  }
  day.duration_s = last_t - first.t.front();
  for (ChannelDay& cd : day.channels) {
    std::string changed, drifting;
    for (Track& tr : cd.tracks) {
      judge_track(tr);
      std::ostringstream s;
      s.precision(4);
      if (tr.verdict == "changed") {
        s << (changed.empty() ? "" : "; ") << tr.name << " " << tr.before << " -> " << tr.after
          << " at " << format_hours(tr.at_s) << " +- " << format_hours(tr.at_sd_s);
        changed += s.str();
      } else if (tr.verdict == "drifting") {
        s << (drifting.empty() ? "" : "; ") << tr.name << " " << std::showpos << tr.slope_per_h
          << std::noshowpos << " " << tr.unit << " per hour";
        drifting += s.str();
      }
    }
    cd.verdict = day.windows < 4 ? "too few windows to track (" + std::to_string(day.windows) +
                                       "; 4 are needed)"
                 : !changed.empty()  ? "changed: " + changed
                 : !drifting.empty() ? "drifting: " + drifting
                                     : "stable";
  }
  return day;
}

}  // namespace planter::analysis
