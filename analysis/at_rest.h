#pragma once
// Where the machine stands, found at the recording's own rate and resolution, and carried
// through the decimation as a column of its own (issue 32: the anti-alias filter leaves no
// exact zeros, so a thinned recording never showed a standstill).
#include <string>
#include <vector>

#include "analysis/recording.h"

namespace planter::analysis {

// The column the analysed recording carries: 1 at rest, 0 moving. Its name cannot be a
// recording column (they are identifiers; see docs/recording-format.md).
inline const std::string kAtRestColumn = "(at rest)";

// Half the window a standstill must last: covers the soil wheel's estimator lag at a start.
inline constexpr double kRestHalfWindow_s = 0.5;

// True where the soil wheel's speed reads zero (no encoder edge) for kRestHalfWindow_s either
// side, which covers the wheel's estimator lag at a start. Read at the recording's own rate
// and resolution: a cell written "0.00000" is zero to its last decimal. A speed that never
// reads zero (a filtered estimate) marks nothing.
std::vector<bool> wheel_at_rest(const Recording& r);

}  // namespace planter::analysis
