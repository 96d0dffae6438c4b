#pragma once
// How the analysis shortens a long recording without aliasing: each column it reads is low-pass
// filtered with zero phase, then every k-th row is kept. A vibration above the kept rate's
// Nyquist frequency is removed, not folded down to a false, slow one.
#include <string>
#include <vector>

#include "analysis/recording.h"

namespace planter::analysis {

// The low-pass cut-off as a share of the decimated Nyquist frequency.
inline constexpr double kAntiAliasCutoffShare = 0.8;
// The low-pass cut-off for rows thinned to `thinned_rate_hz`.
inline double anti_alias_cutoff_hz(double thinned_rate_hz) {
  return kAntiAliasCutoffShare * 0.5 * thinned_rate_hz;
}

// A fourth-order Butterworth low-pass run forwards and backwards (zero phase, eighth-order
// magnitude; Oppenheim & Schafer, "Discrete-Time Signal Processing", 3rd ed., sec. 7.3 for the
// bilinear design, and Gustafsson, IEEE Trans. Signal Processing 44(4), 1996, for
// forward-backward filtering with its start-up transients removed). `cutoff_hz` and the sample
// rate `rate_hz`; the signal is taken as evenly sampled.
void zero_phase_lowpass(std::vector<double>& x, double cutoff_hz, double rate_hz);

// Every `stride`-th row; the named columns first filtered below kAntiAliasCutoffShare of the new
// Nyquist frequency, except a command (the signal table's commanded columns), which is averaged
// over each kept row's interval: the filter would ring at its steps. Other columns and the
// state are only thinned (a flag has no spectrum). A filtered column named in `travel` is also
// kept whole at its own rate (Recording::travel), for rate-independent effects.
Recording decimated(const Recording& r, std::size_t stride, const std::vector<std::string>& filter,
                    const std::vector<std::string>& travel = {});

// A column at a recording's own rate `rate_hz`, filtered and thinned as decimated() does the
// columns it filters: what a row of the thinned recording holds of it.
std::vector<double> thinned_as_filtered(std::vector<double> v, std::size_t stride, double rate_hz);

// What the anti-alias filter leaves of a sinusoid of `f_hz` in a recording thinned by
// decimated() (1 when it was not thinned): the zero-phase filter's magnitude, the Butterworth's
// squared, 1 / (1 + (tan(pi f / fs) / tan(pi fc / fs))^8) at the recording's own rate fs. A
// fitted vibration passes through it as the recorded one did: at 7 Hz under a 13.3 Hz cut-off it
// is 0.994, and an amplitude fitted without it read 0.6 % low.
double anti_alias_gain(const Recording& r, double f_hz);

// The mean sample rate of a recording, Hz.
double sample_rate_hz(const Recording& r);

}  // namespace planter::analysis
