#pragma once
// Periodic content of a residual: a sinusoid's amplitude and phase at a frequency by projection,
// its frequency refined by golden-section search, and the tones of a whole recording at its own
// rate (above the rate the analysis decimates to), found in its spectrum.
#include <cstddef>
#include <vector>

namespace planter::analysis {

// A sinusoid that, added to the prediction, matches the residual's periodic part:
// residual = prediction - y, so the tone projects -residual.
struct Tone {
  double amplitude = 0.0;
  double frequency_hz = 0.0;
  double phase_rad = 0.0;  // of amplitude * sin(2 pi f t + phase)
};

// Over samples [0, n).
Tone project_tone(const std::vector<double>& t, const std::vector<double>& residual, std::size_t n,
                  double frequency_hz);
// The strongest tone between lo_hz and hi_hz, by golden-section search on its power.
Tone refine_tone(const std::vector<double>& t, const std::vector<double>& residual, std::size_t n,
                 double lo_hz, double hi_hz);

struct FastTone {
  Tone tone;
  int order = 0;                // a multiple of the lowest tone found (0: not a harmonic of it)
  double fundamental_hz = 0.0;  // that lowest tone
  double held_out_rms_before = 0.0;  // the residual's RMS on the held-out part, without it ...
  double held_out_rms_after = 0.0;   // ... and with it subtracted
  // Standard deviations of amplitude, frequency and phase: the Cramer-Rao bounds for a sinusoid
  // in white noise (Rife & Boorstyn 1974, IEEE Trans. Inf. Theory 20(5)), with the noise's
  // density taken from the spectrum's floor around the tone (coloured noise counts as it is).
  double amplitude_sd = 0.0, frequency_sd_hz = 0.0, phase_sd_rad = 0.0;
};

// Tones of a residual between from_hz and 0.45 times the sample rate, at most max_tones,
// strongest first: a spectral peak that stands above its neighbourhood's median with a
// false-alarm chance under 1e-3 for the whole spectrum, refined on the calibration part
// [0, calibration_end), and at least as large as the white noise left once the tones are
// removed. Samples are taken as evenly spaced for the spectrum; the refinement uses their times.
std::vector<FastTone> find_fast_tones(const std::vector<double>& t,
                                      const std::vector<double>& residual, double from_hz,
                                      std::size_t calibration_end, int max_tones = 3);

}  // namespace planter::analysis
