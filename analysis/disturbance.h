#pragma once
// An unmeasured disturbance along the row as a named random process (issue 52, item 1): the
// terrain under the depth wheel, the soil wheel's slip, the stems' spread in the clamp's nip.
// A field log has no sensor for them; where the simulator's known_* column is absent, the
// channel's residual is read as that process seen through the channel's sensitivity to it,
// plus white noise, and the process's size and scale along the row are fitted.
//
// The form: a second-order Gauss-Markov process in the distance travelled s,
//   d'' + 2 zeta omega d' + omega^2 d = w(s),  stationary variance sigma^2,
// beside a constant mean: the textbook's shaping filter for a stationary random road or field
// profile with a dominant wavelength 2 pi / omega (Gelb, "Applied Optimal Estimation", 1974,
// sec. 3.8; Dodds & Robson, J. Sound Vib. 31, 1973, for terrain as a process of distance). With
// zeta of 1 or more it is a low-pass process of correlation length 2 zeta / omega. Along
// distance, so that a machine at rest sees one unchanging value. The residual e[k] =
// g[k] (d + mean) + n[k], n white of variance R, is a linear state-space model; its likelihood
// comes from the Kalman filter's innovations (Harvey, "Forecasting, Structural Time Series
// Models and the Kalman Filter", 1989, sec. 3.4), R concentrated out of it. The parameters:
// sigma, omega, zeta (three, and R).
#include <optional>
#include <string>
#include <vector>

namespace planter::analysis {

struct DisturbanceSpec {
  std::string name;             // in the machine's words: "terrain under the depth wheel"
  std::string unit;             // the process's unit as shown: "mm", "%"
  double shown_per_unit = 1.0;  // a slip fraction is shown in %
};

struct DisturbanceFit {
  const DisturbanceSpec* spec = nullptr;
  double rms = 0.0, rms_sd = 0.0;  // sigma, in the process's own unit
  // Along the row: the dominant wavelength (periodic) or the correlation length, and its SD.
  double scale_m = 0.0, scale_sd_m = 0.0;
  bool periodic = false;  // zeta under 0.5: a wavelength shows in its spectrum
  double step_m = 0.0;    // the rows' median travel, what the rows resolve along the row
  double zeta = 0.0;
  double mean = 0.0;                // the constant part, as filtered at the last calibration row
  double noise_rms = 0.0;           // the white noise under it, sqrt(R)
  double delta_bic = 0.0;           // against the constant and white noise alone, calibration rows
  double rms_held_out = 0.0;        // of the one-step innovations on the held-out rows
  double predicted_held_out = 0.0;  // the RMS the model gives them there, sqrt(mean S)
  // Share of lags 1-50 where the calibration rows' standardised innovations correlate beyond
  // +-1.96 / sqrt(N): a process that explains the residual leaves them white.
  double whiteness_violations = 0.0;
  double neg2ll = 0.0;  // -2 log-likelihood of the calibration rows

  // The fitted shape, as the filter runs it (standardised_innovations).
  struct Shape {
    std::vector<double> gain, step_m;  // the gain normalised to an RMS of 1; each row's step
    double lambda_m = 0.0, zeta = 0.0, q = 0.0, prior_b = 0.0;
    std::size_t skip = 0;
  } shape;

  [[nodiscard]] std::string describe() const;  // "terrain under ...: 3.2 mm RMS over 0.45 m"
};

// The process fitted by maximum likelihood on rows [0, calibration_end) of `residual`, then
// filtered over every row with those values. `gain` is the residual's sensitivity to the
// process at each row, `distance_m` the distance travelled at each row (non-decreasing). nullopt
// where the rows are too few to say anything (under 50) or the gain is nowhere non-zero.
// `near`: a fit of the same process on a nearby residual (the same channel refitted); its shape
// starts the search, which then skips the grid.
std::optional<DisturbanceFit> fit_disturbance(const DisturbanceSpec& spec,
                                              const std::vector<double>& gain,
                                              const std::vector<double>& distance_m,
                                              const std::vector<double>& residual,
                                              std::size_t calibration_end,
                                              const DisturbanceFit* near = nullptr);

// e (a residual over the recording's first e.size() rows) replaced by the process's one-step
// innovations over the SD the filter gives each, with the fitted shape and gains held: linear in
// e, the rows before the constant is known set to 0. A fit that minimises their squares is a
// prediction-error fit beside the process.
void standardised_innovations(const DisturbanceFit& d, std::vector<double>& e);

}  // namespace planter::analysis
