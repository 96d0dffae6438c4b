#pragma once
// Single-sample glitches: a sample far from both its neighbours, which agree with each other
// (a 65535 from a load cell's bus error, a dropped bit). Left in, one of them inflates the noise
// estimate and the fit's residual by orders of magnitude and hides a real mismatch; so each is
// excluded (replaced by its neighbours' mean) and reported by column, time and value.
#include <string>
#include <vector>

#include "analysis/recording.h"

namespace planter::analysis {

struct Glitch {
  std::string column;
  double t_s = 0.0;
  double value = 0.0;        // what the recording said
  double replaced_by = 0.0;  // the neighbours' mean the analysis used
};

// The glitches of the named columns. A spike must stand out from both neighbours by more
// than max(20 x the 90th percentile of the column's sample-to-sample steps, a fifth of its
// 1-99 % range), so noise, vibration, steps and ramps are never taken for one.
// Only the named columns are searched: those the channels read (a derived column such as sigma,
// R omega / v, is wild near standstill by definition, not by a fault).
std::vector<Glitch> find_glitches(const Recording& r, const std::vector<std::string>& columns);
// A copy of `r` with the glitches replaced.
Recording without_glitches(const Recording& r, const std::vector<Glitch>& glitches);

}  // namespace planter::analysis
