#pragma once
// A parameter that changes once during a recording (a new seedling batch stiffens the clamp, the
// soil gets heavier): the channel's whole model is refitted before and after a switch time, the
// time found by a search over the calibration part with the BIC as its penalty (a structural
// break test: Chow, Econometrica 28(3), 1960; the penalised search after Bai & Perron,
// Econometrica 66(1), 1998). The parameters that moved are named with their values either side.
#include <optional>
#include <string>
#include <vector>

#include "analysis/channel_fit.h"

namespace planter::analysis {

struct ParameterChange {
  std::string name;
  std::string unit;
  double before = 0.0, before_sd = 0.0;
  double after = 0.0, after_sd = 0.0;
};

struct ChangePoint {
  double at_s = 0.0;
  double at_sd_s = 0.0;    // half the span of switch times within one unit of BIC of the best
  double delta_bic = 0.0;  // against the fit without a change
  // The one parameter that changed, and those that fit as well (a tie); or, when no one alone
  // accounts for the change, all that moved clearly, largest move first.
  std::vector<ParameterChange> changed;
  bool tied = false;               // changed[0] or any of the others: this recording cannot tell
  ChannelFit before, after;        // the model fitted on either side
  std::vector<double> prediction;  // before's up to the switch, after's from it
  double rms_calibration = 0.0;
  double rms_held_out = 0.0;  // predicted with the values after the switch
};

// The best single switch time for `fit` on `split`'s calibration part, with both sides at least
// a tenth of it; nullopt when the recording is too short to split. `noise_rms`: the output's
// white measurement noise.
std::optional<ChangePoint> find_change_point(const ChannelModel& channel, const Recording& r,
                                             const Split& split, const ChannelFit& fit,
                                             double noise_rms);

}  // namespace planter::analysis
