#pragma once
// planter-fit's analysis of one recording: for every observable channel, calibrate the
// nominal structure, locate where its residual concentrates, score the named candidate
// effects (and pairs) by BIC and held-out error, and refit the chosen ones.
#include <optional>
#include <string>
#include <vector>

#include "analysis/channel_report.h"
#include "analysis/day_report.h"
#include "analysis/glitches.h"

namespace planter::analysis {

struct FitReport {
  std::string file;
  FitOptions options;  // the criteria the candidates were held to
  std::size_t rows = 0;
  std::size_t analysed_rows = 0;   // after decimation
  double rate_hz = 0.0;            // the recording's sample rate
  double analysed_up_to_hz = 0.0;  // the anti-alias cut-off (the rate's Nyquist if none)
  double duration_s = 0.0;
  Split split;
  double held_out_from_s = 0.0;
  std::vector<ChannelReport> channels;
  std::vector<std::string> unobservable;  // channels whose columns are missing
  // Known disturbances the recording carries and the channels took as inputs: "column (channel)".
  std::vector<std::string> known_inputs;
  std::vector<Glitch> glitches;  // samples excluded as single-sample glitches
  // Where the machine left nominal operation (a fault or the e-stop in the state column): the
  // rows from there on are not analysed. Empty when it never did.
  std::string stopped_state;
  double stopped_at_s = 0.0;
  std::size_t stopped_rows = 0;  // rows left out
  std::optional<DayReport> day;  // a recording longer than one window: across it
};

// Marks a dead zone on the disc's speed that the disc torque's dry friction explains through a
// proportional speed loop (ChannelReport::ExplainedBy, kThroughSpeedLoop). analyse() calls it.
void judge_speed_loop_deficit(FitReport& rep);

// Throws RecordingError when no channel is observable. Glitches are excluded first
// (glitches.h) and listed in the report.
FitReport analyse(const Recording& r, const FitOptions& o);
// What the analysis works on: the recording without its glitches, decimated to at most
// max_rows with the columns the channels read low-pass filtered first (decimation.h).
Recording analysed_recording(const Recording& r, const FitOptions& o,
                             const std::vector<Glitch>& glitches);
// The rows a report's predictions cover, as analyse() analysed them: `whole` up to its first
// fault (FitReport::stopped_rows left out), without its glitches, decimated. The report's plots
// read these with the predictions, row for row.
Recording analysed_rows_of(const Recording& whole, const FitReport& rep);
// The columns the channels read, each once.
std::vector<std::string> channel_columns();

}  // namespace planter::analysis
