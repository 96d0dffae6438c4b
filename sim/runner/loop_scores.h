#pragma once
// Each loop scored against its goal (firmware/control/loop_goals.h) from the ground truth, tick
// by tick: how far off (RMS, worst), how long its longest stretch out of the goal lasted, and
// whether an alarm of its own (or a fault) rose within a second of it first leaving the goal.
// The disturbance suite (planter-sim robustness) reads these from every run's summary.json.
#include <cstdint>
#include <string>

#include "firmware/control/loop_goals.h"
#include "firmware/controller/telemetry.h"
#include "sim/plant/plant.h"

namespace planter::sim {

// Samples count towards sigma while the machine moves at least this fast: below it, sigma
// = R*omega/v divides by almost nothing (stops and the first centimetres of a start).
constexpr double kSigmaMinSpeedMps = 0.02;

enum class Verdict { held, alarmed, silent };
const char* verdict_name(Verdict v);

struct LoopScore {
  double rms = 0, worst = 0;   // sigma: % of target; clamp: N; depth: mm
  double in_band_pct = 100;    // clamp and depth: share of judged time in the band
  double longest_out_s = 0;    // the longest stretch out of the goal
  double left_goal_at_s = -1;  // when the loop first left its goal (-1: never)
  double alarm_at_s = -1;      // the first of its alarms or a fault (-1: none)
  double above_ceiling_s = 0;  // clamp: time the true force spent above the ceiling
  bool goal_met = true;
  Verdict verdict = Verdict::held;
};

struct LoopScores {
  LoopScore sigma, clamp, depth;
};

class LoopScorer {
 public:
  void configure(double sigma, double ceiling_N, double depth_ramp_s, double period_s) {
    sigma_ = sigma;
    ceiling_N_ = ceiling_N;
    depth_ramp_s_ = depth_ramp_s;
    period_s_ = period_s;
  }
  void add(const Telemetry& c, const PlantTruth& t, double time_s);
  [[nodiscard]] LoopScores finish() const;

 private:
  struct Stretch {  // a loop's run of ticks out of its goal
    double out_s = 0, longest_s = 0;
    double first_at_s = -1;   // the start of the first stretch of at least min_s
    double first_any_s = -1;  // the first tick out at all
    void out(double at_s, double dt_s, double min_s);
    void in() { out_s = 0; }
  };
  // A loop judged against a band (clamp: per seedling; depth: per tick).
  struct BandTally {
    double err2 = 0, worst = 0;
    std::uint64_t n = 0, in = 0;
    Stretch out;
    void add(double error, bool in_band, double at_s, double dt_s, double onset_s);
    void fill(LoopScore& s) const;
    [[nodiscard]] double left_goal_at_s() const {
      return out.first_at_s >= 0 ? out.first_at_s : out.first_any_s;
    }
  };
  void add_sigma(const PlantTruth& t, bool running, double time_s);
  void close_sigma_window(bool whole);

  LoopGoals goals_ = kLoopGoals;
  double sigma_ = 1.5, ceiling_N_ = 120.0, depth_ramp_s_ = 6.0, period_s_ = 0.01;
  bool was_running_ = false;
  double running_since_s_ = 0, moving_since_s_ = -1;
  // sigma
  double sigma_err2_ = 0, window_sum_ = 0, window_start_s_ = -1, worst_window_ = 0;
  std::uint64_t sigma_n_ = 0, window_n_ = 0;
  double first_over_worst_s_ = -1, first_over_rms_s_ = -1;
  Stretch sigma_out_;
  // clamp: each seedling's passage through the nip
  void add_clamp(const Telemetry& c, const PlantTruth& t, bool running, double time_s);
  void close_passage();
  BandTally clamp_;
  double above_ceiling_s_ = 0, first_above_s_ = -1;
  std::size_t passage_id_ = 0;
  double passage_sum_N_ = 0, passage_setpoint_N_ = 0, passage_start_s_ = 0;
  std::uint64_t passage_ticks_ = 0;
  BandTally depth_;
  // the first tick each loop's alarms (or a fault) held
  double sigma_alarm_s_ = -1, clamp_alarm_s_ = -1, depth_alarm_s_ = -1;
};

// "loops" in summary.json, and back.
std::string loop_scores_json(const LoopScores& s);  // one JSON object
std::string loop_score_json(const LoopScore& s);    // one loop's, as inside it
LoopScores loop_scores_from_json(const std::string& text);

}  // namespace planter::sim
