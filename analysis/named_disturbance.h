#pragma once
// The unmeasured disturbance a channel carries, judged (issue 52, items 1 and 3): fitted on the
// final fit's residual where the recording lacks the disturbance's known_* column, named when it
// earns its parameters, and every effect chosen before it judged again beside it.
#include "analysis/channel_report.h"

namespace planter::analysis {

// Sets c.disturbance when the process earns its place: it lowers BIC by FitOptions::
// min_delta_bic against white noise, its size is two SD from none, and its one-step predictions
// lower the held-out RMS by min_improvement. An effect chosen before it stays only if, beside
// it, the effect still lowers the held-out innovations by min_improvement; one that does not
// is left out with a note in c.beside_disturbance, and the final fit is refitted without it.
void name_disturbance(ChannelReport& c, const Recording& r, const Split& split,
                      const FitOptions& o);

}  // namespace planter::analysis
