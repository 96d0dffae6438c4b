#include "analysis/tones.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <unsupported/Eigen/FFT>

#include "analysis/residual_stats.h"

namespace planter::analysis {
namespace {

void subtract(const std::vector<double>& t, const Tone& tone, std::vector<double>& e) {
  // The tone matches -residual: adding it to the prediction removes it from the residual.
  for (std::size_t k = 0; k < e.size(); ++k)
    e[k] += tone.amplitude *
            std::sin(2.0 * std::numbers::pi * tone.frequency_hz * t[k] + tone.phase_rad);
}

}  // namespace

Tone project_tone(const std::vector<double>& t, const std::vector<double>& residual, std::size_t n,
                  double frequency_hz) {
  double a = 0, b = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double w = 2.0 * std::numbers::pi * frequency_hz * t[k];
    a -= residual[k] * std::sin(w);
    b -= residual[k] * std::cos(w);
  }
  a *= 2.0 / static_cast<double>(n);
  b *= 2.0 / static_cast<double>(n);
  return {std::sqrt(a * a + b * b), frequency_hz, std::atan2(b, a)};
}

Tone refine_tone(const std::vector<double>& t, const std::vector<double>& residual, std::size_t n,
                 double lo_hz, double hi_hz) {
  for (int it = 0; it < 40; ++it) {
    const double m1 = lo_hz + 0.382 * (hi_hz - lo_hz), m2 = lo_hz + 0.618 * (hi_hz - lo_hz);
    if (project_tone(t, residual, n, m1).amplitude > project_tone(t, residual, n, m2).amplitude)
      hi_hz = m2;
    else
      lo_hz = m1;
  }
  return project_tone(t, residual, n, 0.5 * (lo_hz + hi_hz));
}

std::vector<FastTone> find_fast_tones(const std::vector<double>& t,
                                      const std::vector<double>& residual, double from_hz,
                                      std::size_t calibration_end, int max_tones) {
  std::vector<FastTone> found;
  const std::size_t end = std::min(calibration_end, residual.size());
  if (end < 64) return found;
  const double rate = static_cast<double>(end - 1) / (t[end - 1] - t[0]);
  const double to_hz = 0.45 * rate;
  if (from_hz >= to_hz) return found;
  std::vector<double> e = residual;
  for (int round = 0; round < max_tones; ++round) {
    // Hann-windowed periodogram of the calibration part, mean removed, zero-padded to 2^m.
    std::size_t nfft = 1;
    while (nfft < end) nfft *= 2;
    double mean = 0;
    for (std::size_t k = 0; k < end; ++k) mean += e[k] / static_cast<double>(end);
    // On an even grid, interpolated: jittered sampling wanders in phase (a 1 ms walk at
    // 30 Hz turns a tone into a smear); the refinement below uses the true times.
    std::vector<double> x(nfft, 0.0);
    double window_power = 0.0;  // sum of the Hann window's squares: a bin's noise power / s^2
    const double step = (t[end - 1] - t[0]) / static_cast<double>(end - 1);
    std::size_t j = 0;
    for (std::size_t k = 0; k < end; ++k) {
      const double at = t[0] + step * static_cast<double>(k);
      while (j + 2 < end && t[j + 1] < at) ++j;
      const double share = std::clamp((at - t[j]) / (t[j + 1] - t[j]), 0.0, 1.0);
      const double v = e[j] + share * (e[j + 1] - e[j]);
      const double w = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(k) /
                                            static_cast<double>(end - 1));
      x[k] = (v - mean) * w;
      window_power += w * w;
    }
    std::vector<std::complex<double>> spectrum;
    Eigen::FFT<double> fft;
    fft.fwd(spectrum, x);
    const double bin_hz = rate / static_cast<double>(nfft);
    const auto lo = static_cast<std::size_t>(std::ceil(from_hz / bin_hz));
    const auto hi = static_cast<std::size_t>(std::floor(to_hz / bin_hz));
    if (hi <= lo + 8) break;
    std::vector<double> power(hi - lo);
    for (std::size_t k = lo; k < hi; ++k) power[k - lo] = std::norm(spectrum[k]);
    // The floor: the median of blocks of 257 bins (a peak is a few bins; the median ignores it).
    constexpr std::size_t kBlock = 257;
    std::vector<double> floor_of(power.size());
    for (std::size_t b = 0; b < power.size(); b += kBlock) {
      const std::size_t a =
          b + kBlock > power.size() && power.size() > kBlock ? power.size() - kBlock : b;
      std::vector<double> block(
          power.begin() + static_cast<long>(a),
          power.begin() + static_cast<long>(std::min(power.size(), a + kBlock)));
      std::nth_element(block.begin(), block.begin() + static_cast<long>(block.size() / 2),
                       block.end());
      for (std::size_t k = b; k < std::min(power.size(), b + kBlock); ++k)
        floor_of[k] = block[block.size() / 2];
    }
    // Noise power in a bin is exponential: P(above c * median) = 2^-c. Over all bins the
    // chance of a false peak stays under 1e-3.
    const double c = std::log2(static_cast<double>(power.size()) * 1000.0);
    std::size_t best = 0;
    double best_ratio = 0.0;
    for (std::size_t k = 0; k < power.size(); ++k) {
      const double ratio = floor_of[k] > 0 ? power[k] / floor_of[k] : 0.0;
      if (ratio > best_ratio) best_ratio = ratio, best = k;
    }
    if (best_ratio < c) break;
    const double f = static_cast<double>(best + lo) * bin_hz;
    FastTone ft;
    ft.tone = refine_tone(t, e, end, f - 3.0 * bin_hz, f + 3.0 * bin_hz);
    // The floor is a median; an exponential's mean is its median / ln 2.
    const double noise_var = floor_of[best] / (std::log(2.0) * window_power);
    const double n = static_cast<double>(end);
    const double a2 = std::max(ft.tone.amplitude * ft.tone.amplitude, 1e-300);
    ft.amplitude_sd = std::sqrt(2.0 * noise_var / n);
    ft.frequency_sd_hz =
        std::sqrt(24.0 * noise_var / (a2 * n * (n * n - 1.0))) / (2.0 * std::numbers::pi * step);
    ft.phase_sd_rad = std::sqrt(8.0 * noise_var / (a2 * n));
    ft.held_out_rms_before = rms_between(e, end, e.size());
    subtract(t, ft.tone, e);
    ft.held_out_rms_after = rms_between(e, end, e.size());
    found.push_back(ft);
  }
  // Only tones at least as large as the white noise left: smaller ones are no physics to act on.
  const double noise = white_noise_rms(e, end);
  std::erase_if(found, [&](const FastTone& f) { return f.tone.amplitude < noise; });
  if (found.empty()) return found;
  double fundamental = found[0].tone.frequency_hz;
  for (const auto& f : found) fundamental = std::min(fundamental, f.tone.frequency_hz);
  for (auto& f : found) {
    const double ratio = f.tone.frequency_hz / fundamental;
    const double order = std::round(ratio);
    f.fundamental_hz = fundamental;
    f.order = std::abs(ratio - order) < 0.02 * order ? static_cast<int>(order) : 0;
  }
  return found;
}

}  // namespace planter::analysis
