#include "analysis/decimation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "analysis/residual_stats.h"
#include "firmware/io/signal_table.h"

namespace planter::analysis {
namespace {

// One second-order section, direct form II transposed, with its state.
struct Biquad {
  double b0, b1, b2, a1, a2;
  double z1 = 0.0, z2 = 0.0;
  // Starts from the steady state of the input `x0`: no step at the start, the filter has always
  // seen it. Returns the first output.
  double start(double x0) {
    const double gain = (b0 + b1 + b2) / (1.0 + a1 + a2);  // 1 for a low-pass
    const double y0 = gain * x0;
    z1 = y0 - b0 * x0;
    z2 = b2 * x0 - a2 * y0;
    return step(x0);
  }
  double step(double in) {
    const double out = b0 * in + z1;
    z1 = b1 * in - a1 * out + z2;
    z2 = b2 * in - a2 * out;
    return out;
  }
};

// Two sections in cascade over x in place, forwards or backwards. One loop runs
// both: the second section's recurrence overlaps the first's on the next row (each is a chain
// of dependent multiply-adds), the same operations in the same order as two passes.
// Where the input holds one value the sections settle into a cycle of their last bits' rounding
// (a fixed point, or a few rows). Every 16th row of held input the state is watched over the
// next rows: once it recurs, each row on to the input's next change repeats the cycle's
// output, bit for bit, and is copied. A held clamp or a still roller is most of a recording's
// rows, and a fit filters the clamp's hysteresis path thousands of times: on a 10-minute
// recording's path, 36 % of the rows copied, the filter 0.68 of its time; the cycles were of 1
// and 4 rows (watching for up to 16 found no more), and watching every row cost more than it
// saved.
void run_cascade(Biquad first, Biquad second, std::vector<double>& x, bool forwards) {
  constexpr std::size_t kLongestCycle = 4, kWatchEvery = 16;
  const std::size_t n = x.size();
  auto at = [&](std::size_t i) -> double& { return x[forwards ? i : n - 1 - i]; };
  auto state = [&] { return std::array<double, 4>{first.z1, first.z2, second.z1, second.z2}; };
  double in = at(0);
  at(0) = second.start(first.start(in));
  std::size_t held = 0;  // rows before this one with its input
  for (std::size_t i = 1; i < n; ++i) {
    held = at(i) == in ? held + 1 : 0;
    in = at(i);
    at(i) = second.step(first.step(in));
    if (held % kWatchEvery != kWatchEvery - 1) continue;
    const std::array<double, 4> watched = state();
    std::size_t cycle = 0;
    for (std::size_t c = 1; c <= kLongestCycle && i + 1 < n && at(i + 1) == in; ++c) {
      ++i, ++held;
      at(i) = second.step(first.step(in));
      if (state() == watched) {
        cycle = c;
        break;
      }
    }
    if (cycle == 0) continue;
    std::size_t last = i;
    for (; last + 1 < n && at(last + 1) == in; ++last) at(last + 1) = at(last + 1 - cycle);
    // The state after the last copied row: the watched one, stepped on to its phase.
    first.z1 = watched[0], first.z2 = watched[1], second.z1 = watched[2], second.z2 = watched[3];
    for (std::size_t step = 0; step < (last - i) % cycle; ++step) second.step(first.step(in));
    i = last;
  }
}

// Low-pass section with quality q, by the bilinear transform with pre-warping.
Biquad lowpass(double cutoff_hz, double rate_hz, double q) {
  const double k = std::tan(std::numbers::pi * cutoff_hz / rate_hz);
  const double norm = 1.0 / (1.0 + k / q + k * k);
  const double b0 = k * k * norm;
  return {b0, 2.0 * b0, b0, 2.0 * (k * k - 1.0) * norm, (1.0 - k / q + k * k) * norm};
}

}  // namespace

void zero_phase_lowpass(std::vector<double>& x, double cutoff_hz, double rate_hz) {
  if (x.size() < 3 || cutoff_hz <= 0.0 || cutoff_hz >= 0.5 * rate_hz) return;
  // Fourth-order Butterworth: two sections with the poles' quality factors
  // 1 / (2 cos(pi/8)) and 1 / (2 cos(3 pi/8)).
  const Biquad first = lowpass(cutoff_hz, rate_hz, 0.5411961001461969);
  const Biquad second = lowpass(cutoff_hz, rate_hz, 1.3065629648763766);
  run_cascade(first, second, x, true);
  run_cascade(first, second, x, false);
}

double sample_rate_hz(const Recording& r) {
  if (r.size() < 2) return 0.0;
  return static_cast<double>(r.size() - 1) / (r.t.back() - r.t.front());
}

double anti_alias_gain(const Recording& r, double f_hz) {
  const double stride = static_cast<double>(r.decimation_stride);
  const double rate = sample_rate_hz(r) * stride;  // the recording's own rate
  if (r.decimation_stride <= 1 || rate <= 0.0) return 1.0;
  const double cutoff = anti_alias_cutoff_hz(rate / stride);
  const double f = std::min(std::abs(f_hz), 0.4999 * rate);
  const double ratio =
      std::tan(std::numbers::pi * f / rate) / std::tan(std::numbers::pi * cutoff / rate);
  return 1.0 / (1.0 + std::pow(ratio, 8));
}

namespace {

// Every stride-th row of `v`, each the average over its row's interval, centred on the row (no
// delay; half weights at the ends of an even stride).
std::vector<double> interval_averaged(const std::vector<double>& v, std::size_t stride) {
  std::vector<double> o;
  o.reserve(v.size() / stride + 1);
  const double half = 0.5 * static_cast<double>(stride);
  const auto reach = static_cast<std::size_t>(half);
  for (std::size_t k = 0; k < v.size(); k += stride) {
    double sum = 0.0, weight = 0.0;
    const std::size_t from = k >= reach ? k - reach : 0;
    const std::size_t to = std::min(v.size() - 1, k + reach);
    for (std::size_t j = from; j <= to; ++j) {
      const double distance = std::abs(static_cast<double>(j) - static_cast<double>(k));
      const double w = distance < half ? 1.0 : 0.5;
      sum += w * v[j];
      weight += w;
    }
    o.push_back(sum / weight);
  }
  return o;
}

}  // namespace

std::vector<double> thinned_as_filtered(std::vector<double> v, std::size_t stride, double rate_hz) {
  zero_phase_lowpass(v, anti_alias_cutoff_hz(rate_hz / static_cast<double>(stride)), rate_hz);
  std::vector<double> o;
  o.reserve(v.size() / stride + 1);
  for (std::size_t k = 0; k < v.size(); k += stride) o.push_back(v[k]);
  return o;
}

Recording decimated(const Recording& r, std::size_t stride, const std::vector<std::string>& filter,
                    const std::vector<std::string>& travel) {
  if (stride <= 1) return r;
  Recording out = without_rows(r);
  out.decimation_stride = r.decimation_stride * stride;
  const double rate = sample_rate_hz(r);
  for (std::size_t k = 0; k < r.size(); k += stride) out.t.push_back(r.t[k]);
  for (const auto& [name, v] : r.signals) {
    auto& o = out.signals[name];
    o.reserve(out.t.size());
    const SignalDecl* decl = find_signal(name);
    if (std::find(filter.begin(), filter.end(), name) == filter.end()) {
      for (std::size_t k = 0; k < v.size(); k += stride) o.push_back(v[k]);
    } else if (decl != nullptr && decl->commanded != nullptr) {
      // A command is a staircase the controller held: the low-pass filter rings at its
      // steps (a play or a dead zone then reads the ringing: a 6 mm play read 8.5 mm, issue
      // 32), so it is averaged over each kept row's interval instead. The actuator integrates
      // the staircase; the average keeps that integral.
      o = interval_averaged(v, stride);
    } else {
      out.full_rate_noise.emplace(name, white_noise_rms(v, v.size()));
      out.full_rate_grid.emplace(name, value_grid(v));
      out.full_rate_top_rows.emplace(name, rows_at_top(v));
      o = thinned_as_filtered(v, stride, rate);
      if (r.decimation_stride == 1 && std::find(travel.begin(), travel.end(), name) != travel.end())
        out.travel.emplace(name, v);
    }
  }
  for (std::size_t k = 0; k < r.state.size(); k += stride) out.state.push_back(r.state[k]);
  return out;
}

}  // namespace planter::analysis
