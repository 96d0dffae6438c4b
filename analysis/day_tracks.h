#pragma once
// A recording longer than one window (a day in the field): the effects are searched on the
// first window at its own rate (mismatch.h), then the model found is refitted on every window
// as the file is read, a window at a time, so memory stays bounded whatever the length. Each
// fitted parameter's track across the day is judged stable, drifting, or changed at a time.
#include <string>
#include <vector>

#include "analysis/day_report.h"
#include "analysis/mismatch.h"

namespace planter::analysis {

// `first` is the first window, already analysed into `rep`; the reader is at the row after it.
DayReport track_day(RecordingReader& reader, const Recording& first, const FitReport& rep,
                    const FitOptions& o);

// Judges one track (exposed for tests): a constant, a line or one step, by BIC with the track's
// own scatter as its noise, the step or slope also 5 % of the level and 5 of that noise.
void judge_track(Track& track);

}  // namespace planter::analysis
