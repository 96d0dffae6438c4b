#pragma once
// One channel's analysis, in the order planter-fit does it (docs/planter-fit.md, steps 1-4): the
// nominal calibrated, the residual located, the candidate effects judged and chosen, what is left
// judged (a change, an unmeasured disturbance, or a residual unexplained), and the verdict.
#include "analysis/channel_report.h"

namespace planter::analysis {

ChannelReport analyse_channel(const ChannelModel& ch, const Recording& r, const FitOptions& o,
                              const Split& split);

}  // namespace planter::analysis
