#pragma once
// What planter-fit says of one channel (ChannelReport), the candidates it judged on the way, and
// the criteria it held them to (FitOptions).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "analysis/change_points.h"
#include "analysis/channel_fit.h"
#include "analysis/disturbance.h"
#include "analysis/model_file.h"
#include "analysis/tones.h"

namespace planter::analysis {

struct Regime {
  std::string name;        // "near zero input", "at reversals", "after steps", ...
  double rms_ratio = 0.0;  // residual RMS inside the regime over outside it
  double share = 0.0;      // share of the samples in the regime
};

struct Location {
  double whiteness_violations = 0.0;  // share of lags 1-50 outside +-1.96/sqrt(N)
  double input_correlation = 0.0;     // largest |cross-correlation| with the input, lags +-20
  double worst_window_start_s = 0.0;  // of ten windows, the one with the largest RMS
  double worst_window_ratio = 0.0;    // its RMS over the median window's
  double time_correlation = 0.0;      // residual against time (drift)
  double dominant_frequency_hz = 0.0;
  double dominant_amplitude = 0.0;
  std::vector<Regime> regimes;
};

struct Candidate {
  const EffectSpec* spec = nullptr;
  std::string effect;
  double delta_bic = 0.0;             // against the model it would extend
  double held_out_improvement = 0.0;  // 1 - rms_after / rms_before on the held-out part
  double cv_improvement = 0.0;        // blocked cross-validation: the best of 3 folds (or a loss)
  double explained = 0.0;  // share of the calibration residual beyond noise it accounts for
  // The effect's own part of the fit (issue 52): the RMS over the calibration rows of the
  // prediction less the same fit's prediction without it, every other value held; and the
  // RMS it is credited with, sqrt(base's mean square less the fit's). A nominal that refitted
  // better beside the effect gives the effect credit it has not earned (a quantisation step of
  // 0.00046 N against 3.46 N of noise "explained" 70 %): its own part must be half the credit.
  double own_rms = 0.0;
  double credited_rms = 0.0;
  // Non-empty when the recording cannot tell this effect from the nominal's own parameters:
  // why, and the experiment that would (rejection() returns it first).
  std::string not_separable;
  // Non-empty when tried as the second of a pair and a cross-validation fold lost: two effects
  // together bend to the calibration part more freely than one (rejection() returns it next).
  std::string loses_as_pair;
  ChannelFit fit;
};

// Two effects this recording cannot separate: both earn their parameters, and their BIC differ
// by less than FitOptions::tie_delta_bic. The chosen one is kept; the experiment tells them apart.
struct Tie {
  std::string chosen;
  std::string alternative;
  double delta_bic = 0.0;  // the alternative's BIC less the chosen one's
  std::string experiment;
};

struct ChannelReport {
  const ChannelModel* channel = nullptr;
  ChannelFit nominal;
  double noise_rms = 0.0;  // white measurement noise: second differences of the final residual
  // What the output's resolution alone leaves, step / sqrt(12): the floor of noise_rms.
  double resolution_rms = 0.0;
  // The step the output is recorded in, where its rounding sets the floor rather than its noise
  // (resolution_rms at least the white noise at the recording's own rate): a coarse log's steps
  // are named as such, not measured as noise (issue 52). 0 otherwise.
  double logged_step = 0.0;
  // What the measured input's noise makes in the residual through the final fit's nominal
  // (ChannelModel::input_noise_rms); "unexplained" must stand above both.
  double input_noise_rms = 0.0;
  // Set when the held-out residual stands out from the noise but not from the spread the
  // parameters' uncertainty gives the held-out prediction: the parameter that contributes most,
  // which this recording's calibration part does not determine.
  std::string undetermined;
  // Set when the final fit's nominal is degenerate: parameters whose SD is a quarter of their
  // range or more, or as large as a positive one's value (a clamp law fitted at one held force:
  // k_c 1.15 +- 233): "the clamp law undetermined: ...". It sends the change-point search too.
  std::string degenerate;
  Location location;
  std::vector<Candidate> ranked;  // single effects, best BIC first
  std::vector<Candidate> chosen;  // accepted (one or two)
  // When no single effect earns its place but one fails only on the share it explains: the
  // second effects tried beside it, each judged as a pair against the nominal.
  std::vector<Candidate> pairs;
  std::string pairs_beside;  // that first effect
  std::vector<Tie> ties;     // near ties with what was chosen
  // Vibration above the analysed rate, found in the final residual at the recording's own rate.
  std::vector<FastTone> fast_tones;
  // A parameter that changed once, when the fit without it leaves a structured residual and the
  // change earns its parameters by the same rules as an effect. The final fit then holds the
  // values after the change.
  std::optional<ChangePoint> change;
  ChannelFit final_fit;
  // What the full rate said of a time-resolution parameter found on decimated rows.
  std::vector<std::string> refined;
  // An effect named here that is another named effect seen from here, not a second finding:
  // - a stiction beside a Coulomb or Stribeck friction whose breakaway is not above that
  //   friction's level at rest: the same friction holding the disc (a dry friction holds
  //   whatever the drive pushes below its level), not a static friction of its own
  //   (judge_friction_hold; "hold_of" in fit.json);
  // - a dead zone on the disc's speed whose width is what the disc torque's dry friction takes
  //   off the speed through the speed loop (judge_speed_loop_deficit; "through_speed_loop_of").
  // `effect` indexes final_fit.effects; `by` names the other effect as "output:effect";
  // `note` gives the numbers.
  struct ExplainedBy {
    enum class Relation { kHoldAtRest, kThroughSpeedLoop };
    std::size_t effect = 0;
    Relation relation = Relation::kHoldAtRest;
    std::string by, note;
  };
  std::vector<ExplainedBy> explained;
  [[nodiscard]] const ExplainedBy* explained_by(std::size_t effect) const {
    for (const auto& x : explained)
      if (x.effect == effect) return &x;
    return nullptr;
  }
  // An unmeasured disturbance named as a random process along the row (named_disturbance.h),
  // and what it changed: effects left out beside it, or why it was not named.
  std::optional<DisturbanceFit> disturbance;
  std::vector<std::string> beside_disturbance;
  // Where an effect was named beside the process: the process's one-step held-out RMS beside
  // the nominal alone, what the effect is judged against (0 otherwise).
  double one_step_nominal = 0.0;
  std::string verdict;  // "no significant mismatch", "effect(s) found", "unexplained residual",
                        // "disturbance named"
  bool unexplained = false;
  // The final fit's nominal parameters that ended at an edge of their range, as
  // "[effect: ]name = value (range lo to hi): the nominal structure (or the effect's form) may
  // be wrong here", and a residual beside it is not evidence of a missing effect (issue 32,
  // item 1).
  std::vector<std::string> at_range_edge;
};

struct FitOptions {
  double held_out_fraction = 0.3;
  double min_improvement = 0.10;  // a fold's RMS must fall by at least this share
  double min_delta_bic = 20.0;
  double min_explained = 0.5;
  // BIC differences on the scale of Kass & Raftery (JASA 90, 1995): under 6 is no strong
  // evidence either way (a tie); an effect holding a simpler one as a special case must beat it
  // by 10 ("very strong") and explain 5 % more of the residual beyond noise, or the simpler one
  // is named. (Residuals of a closed-loop record are not white, so BIC alone overstates the
  // evidence: the extra parameters must also buy a share of the residual.)
  double tie_delta_bic = 6.0;
  // Candidates are chosen by held-out RMS; within this share of the lowest they tie on it and
  // BIC decides (about the RMS's own sampling error over a few hundred independent rows).
  double held_out_tie = 0.05;
  double nested_delta_bic = 10.0;
  double nested_min_explained = 0.05;
  double min_unexplained_share = 0.005;  // of the output's held-out RMS, to call a residual
  int jobs = 1;
  // Told as each channel's analysis ends (from any worker, one call at a time): for progress.
  std::function<void(std::size_t done, std::size_t total, const std::string& channel)>
      on_channel_done;
  // Told as a channel's analysis takes each step (from any worker, at any time: the callee
  // serialises): for progress on a terminal, where one channel runs for seconds.
  std::function<void(const std::string& channel, const std::string& step)> on_step;
  std::size_t max_rows = 12000;  // longer recordings are decimated to this many rows
  // A recording longer than this many rows is analysed on its first window of them and its
  // model tracked across the rest, window by window (day_tracks.h): 10 minutes at 100 Hz.
  std::size_t window_rows = 60000;
  std::vector<ModelChannel> start_model;  // from --model: start values and known effects
};

// Why a candidate does not earn its place, in words (the first criterion it fails), or "" when
// it does. The analysis decides by this, and the report prints it.
std::string rejection(const Candidate& c, const FitOptions& o);

// The BIC rule's shortfall in words: "lowers BIC by 6.0; 20 is required", or where the change
// raises BIC, "raises BIC by 13.8; it must lower it by 20" (not "lowers BIC by -13.8").
std::string bic_shortfall(double delta_bic, double min_delta_bic);

}  // namespace planter::analysis
