#pragma once
// Fits a channel's nominal parameters, with or without candidate effects, in simulation
// (free-run) error form: Ceres with bounds and a Huber loss on the calibration part; the
// non-smooth parameters (a delay, a gap, a width, a step) on a grid around the solver.
#include <functional>
#include <string>
#include <vector>

#include "analysis/channel_model.h"

namespace planter::analysis {

struct Split {
  std::size_t calibration_end = 0;  // samples [0, end) fit; [end, n) is held out
  // A cross-validation fold: samples [fold_from, fold_to) of the calibration part left out.
  std::size_t fold_from = 0;
  std::size_t fold_to = 0;
};

struct ChannelFit {
  std::vector<double> nominal;
  std::vector<Effect> effects;
  std::vector<double> nominal_sd;
  // The nominal parameters' covariance, row by row (nominal.size() squared; empty where none was
  // estimated): what propagates their uncertainty into a quantity read through them.
  std::vector<double> nominal_covariance;
  // Per nominal parameter, false where moving it changes no fitted row's prediction (a speed
  // limit the rows never reach): not fitted, whatever its value says (empty: not checked).
  std::vector<bool> nominal_exercised;
  std::vector<std::vector<double>> effect_sd;
  double rms_calibration = 0.0;
  double rms_held_out = 0.0;
  double bic = 0.0;  // on the calibration part, residuals thinned to about one per 0.1 s
  int parameters = 0;
  std::vector<double> prediction;  // over all samples
  // How far the parameters' uncertainty moves the held-out prediction: the RMS over the
  // held-out rows of the prediction's SD (J cov J', J the prediction's sensitivity there), and
  // the parameter that contributes most to it (an index into fitted_values(); -1: none).
  double held_out_prediction_sd = 0.0;
  int least_determined = -1;

  // Effect e's parameter k's SD (a grid parameter's: its resolution), 0 where none was stated.
  [[nodiscard]] double effect_sd_of(std::size_t e, std::size_t k) const {
    return e < effect_sd.size() && k < effect_sd[e].size() ? effect_sd[e][k] : 0.0;
  }
};

// What a fit minimises instead of the simulation error where a disturbance process is named
// beside the nominal: the error over the rows it is given, mapped in place to what the least
// squares weighs (a linear filter: the process's standardised one-step innovations, so that the
// fit is a prediction-error fit, Ljung, "System Identification", 2nd ed., 1999, sec. 7.2).
using ResidualFilter = std::function<void(std::vector<double>&)>;

// `hold_located`: grid parameters already located (a first effect's, in a second's fit) are held
// where they are rather than refined around their value.
ChannelFit fit_channel(const ChannelModel& channel, const Recording& r, const Split& split,
                       const std::vector<double>& nominal_start, std::vector<Effect> effects,
                       const ResidualFilter* filter = nullptr, bool hold_located = false);

// The fit's prediction over all of `r`'s rows and its RMS on either side of the split, from
// its values as they are (after they were refined on other rows than `r`'s).
void predict(const ChannelModel& channel, const Recording& r, const Split& split, ChannelFit& fit);

// `fit` refitted on the calibration rows `split` keeps (a fold left out), from its own values,
// the grid parameters kept; with standard deviations, the prediction over all samples and its
// RMS on the held-out part. `rss` (if given) gets the RSS over the fitted rows.
ChannelFit refit(const ChannelModel& channel, const Recording& r, const Split& split,
                 const ChannelFit& fit, double* rss = nullptr);
// Every fitted (non-grid) parameter of a fit, named, in a fixed order: the nominal ones, then
// each effect's.
struct FittedValue {
  std::string name;
  std::string unit;
  double value = 0.0;
  double sd = 0.0;
};
std::vector<FittedValue> fitted_values(const ChannelModel& channel, const ChannelFit& fit);

// Where each fitted (non-grid) parameter of a fit lives, with its spec, in the solver's order
// (the order of fitted_values()): to vary one parameter of a fit by hand.
struct ParameterLayout {
  std::vector<double*> slots;
  std::vector<ParamSpec> specs;
};
ParameterLayout fitted_layout(const ChannelModel& channel, ChannelFit& fit);
// The bounds of the parameters given relative to the output's size (ParamSpec::of_output_size)
// made absolute for the recorded output y.
void bounds_for_output(std::vector<ParamSpec>& specs, const std::vector<double>& y);

// Whether v ended at an edge of p's range: a grid parameter only at its own top (the grid could
// go no further), and a lower bound of 0 is the physics' own limit (no lag, no inertia), an
// answer rather than a sign of a wrong form.
bool at_range_edge(const ParamSpec& p, double v);

// A delay is read no closer than a row of the rows it was read on: the channels hold each row's
// command over the next interval (a zero-order hold), so the fitted delay carries that timing,
// short by up to a row (the outside generator's 0.2 s read 0.1927 s at 100 Hz, 0.1855 s on the
// thinned rows; its grid's +- was 0.002). Its stated SD is made at least that row (issue 52:
// an interval includes the known biases).
void widen_delay_by_row(ChannelFit& fit, const Recording& rows_read);

// How many calibration rows a fit on `split` compares (the n of its BIC).
std::size_t fitted_rows(const Split& split);

// The RMS of pred - y on the rows a fit on `split` compares (a long recording's fit compares
// every k-th calibration row): two fits on the same split are ranked on what they minimised.
double rms_on_fitted_rows(const std::vector<double>& pred, const std::vector<double>& y,
                          const Split& split);

// The fit refitted with a fold left out (split.fold_from..fold_to), starting from `fit`, the
// grid parameters kept; returns the RMS error it then makes on the fold.
double fold_rms(const ChannelModel& channel, const Recording& r, const Split& split,
                const ChannelFit& fit);

// A candidate effect with starting values fitted to this channel's nominal residual.
Effect initial_effect(const EffectSpec& spec, const Recording& r,
                      const std::vector<double>& residual);

double signal_span(const std::vector<double>& v);

}  // namespace planter::analysis
