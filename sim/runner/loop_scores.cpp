#include "sim/runner/loop_scores.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace planter::sim {

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::held:
      return "held";
    case Verdict::alarmed:
      return "alarmed";
    case Verdict::silent:
      return "silent";
  }
  return "";
}

void LoopScorer::Stretch::out(double at_s, double dt_s, double min_s) {
  if (first_any_s < 0) first_any_s = at_s;
  out_s += dt_s;
  longest_s = std::max(longest_s, out_s);
  if (out_s >= min_s && first_at_s < 0) first_at_s = at_s - out_s + dt_s;
}

// A window is judged only whole: a stop cuts the last one short, and a mean over a few ticks
// of braking says nothing of the spacing (the RMS still counts every tick).
void LoopScorer::close_sigma_window(bool whole) {
  if (whole && window_n_ > 0) {
    const double mean_pct = 100.0 * std::abs(window_sum_ / static_cast<double>(window_n_));
    worst_window_ = std::max(worst_window_, mean_pct);
    sigma_err2_ += mean_pct * mean_pct;
    ++sigma_n_;
    if (mean_pct > goals_.sigma.worst_pct) {
      if (first_over_worst_s_ < 0) first_over_worst_s_ = window_start_s_;
      sigma_out_.out(window_start_s_, goals_.sigma.window_s, 0.0);
    } else {
      sigma_out_.in();
    }
    if (mean_pct > goals_.sigma.rms_pct && first_over_rms_s_ < 0)
      first_over_rms_s_ = window_start_s_;
  }
  window_sum_ = 0;
  window_n_ = 0;
  window_start_s_ = -1;
}

namespace {
double share_pct(std::uint64_t in, std::uint64_t n) {
  return n ? 100.0 * static_cast<double>(in) / static_cast<double>(n) : 100.0;
}
}  // namespace

void LoopScorer::BandTally::add(double error, bool in_band, double at_s, double dt_s,
                                double onset_s) {
  err2 += error * error;
  worst = std::max(worst, std::abs(error));
  ++n;
  if (in_band) {
    ++in;
    out.in();
  } else {
    out.out(at_s, dt_s, onset_s);
  }
}

void LoopScorer::BandTally::fill(LoopScore& s) const {
  s.rms = n ? std::sqrt(err2 / static_cast<double>(n)) : 0.0;
  s.worst = worst;
  s.in_band_pct = share_pct(in, n);
  s.longest_out_s = out.longest_s;
}

void LoopScorer::close_passage() {
  if (passage_ticks_ > 0) {
    const double mean_N = passage_sum_N_ / static_cast<double>(passage_ticks_);
    const double e = mean_N - passage_setpoint_N_;
    const double length_s = static_cast<double>(passage_ticks_) * period_s_;
    clamp_.add(e, std::abs(e) <= goals_.clamp.band_pct / 100.0 * passage_setpoint_N_,
               passage_start_s_ + length_s, length_s, goals_.clamp.onset_s);
  }
  passage_ticks_ = 0;
  passage_sum_N_ = 0;
}

// Each seedling's grip: the mean true force over its passage through the nip while running,
// once the set-point has ramped up.
void LoopScorer::add_clamp(const Telemetry& c, const PlantTruth& t, bool running, double time_s) {
  if (t.clamp_force_N > ceiling_N_) {
    above_ceiling_s_ += period_s_;
    if (first_above_s_ < 0) first_above_s_ = time_s;
  }
  // Judged against what the loop aims at for this stem (its own ceiling may hold it below the
  // operator's force), once the set-point has ramped to it.
  const double setpoint = c.clamp_force_cmd_N;
  const bool ramped = setpoint > 0 && setpoint >= c.clamp_force_aim_N - 1e-6;
  const std::size_t id = running && ramped ? t.seedling_in_nip : 0;
  if (id != passage_id_) {
    close_passage();
    passage_id_ = id;
    passage_start_s_ = time_s;
  }
  if (id == 0) return;
  passage_sum_N_ += t.clamp_force_N;
  passage_setpoint_N_ = setpoint;
  ++passage_ticks_;
}

// Judged while running and moving, from after_start_s after each start (or restart).
void LoopScorer::add_sigma(const PlantTruth& t, bool judged, double time_s) {
  if (!judged) {
    close_sigma_window(false);
    return;
  }
  const double e = (t.sigma - sigma_) / sigma_;
  if (window_start_s_ < 0) window_start_s_ = time_s;
  window_sum_ += e;
  ++window_n_;
  if (time_s - window_start_s_ >= goals_.sigma.window_s - 0.5 * period_s_) close_sigma_window(true);
}

void LoopScorer::add(const Telemetry& c, const PlantTruth& t, double time_s) {
  const bool running = c.state == SupervisorState::kRunning;
  const bool moving = t.v_mps >= kSigmaMinSpeedMps;
  if (running && !was_running_) running_since_s_ = time_s;
  if (!(running && moving))
    moving_since_s_ = -1;
  else if (moving_since_s_ < 0)
    moving_since_s_ = time_s;
  was_running_ = running;
  // An alarm of the loop's own, a fault or the e-stop: the operator was told.
  const bool told =
      c.faults != 0 || c.state == SupervisorState::kEStop || c.state == SupervisorState::kFault;
  const auto first = [&](double& at_s, std::uint32_t mask) {
    if (at_s < 0 && (told || (c.warnings & mask) != 0)) at_s = time_s;
  };
  first(sigma_alarm_s_, warning::kSigmaAlarms);
  // Too fast for the disc speaks for the clamp too: the seedlings then come faster than the
  // nip can grip them, and the one thing to do for both is to slow down.
  first(clamp_alarm_s_, warning::kClampAlarms | warning::kTooFastForDisc);
  first(depth_alarm_s_, warning::kDepthAlarms);

  add_sigma(t, moving_since_s_ >= 0 && time_s - moving_since_s_ >= goals_.sigma.after_start_s,
            time_s);

  if (t.clamp_force_N > ceiling_N_) {
    above_ceiling_s_ += period_s_;
    if (first_above_s_ < 0) first_above_s_ = time_s;
  }
  add_clamp(c, t, running, time_s);
  if (running && moving && time_s - running_since_s_ >= depth_ramp_s_) {
    const double e = t.depth_mm - c.depth_target_mm;
    depth_.add(e, std::abs(e) <= goals_.depth.band_mm, time_s, period_s_, goals_.depth.onset_s);
  }
}

namespace {

void judge(LoopScore& s, double alarm_at_s, double within_s) {
  s.alarm_at_s = alarm_at_s;
  if (s.goal_met) {
    s.verdict = Verdict::held;
  } else {
    s.verdict = alarm_at_s >= 0 && alarm_at_s <= s.left_goal_at_s + within_s ? Verdict::alarmed
                                                                             : Verdict::silent;
  }
}

}  // namespace

LoopScores LoopScorer::finish() const {
  LoopScores r;
  LoopScore& g = r.sigma;
  // Both over whole 1 s windows: the RMS of their mean errors, and the worst of them.
  g.rms = sigma_n_ ? std::sqrt(sigma_err2_ / static_cast<double>(sigma_n_)) : 0.0;
  g.worst = worst_window_;
  g.longest_out_s = sigma_out_.longest_s;
  const bool worst_failed = g.worst > goals_.sigma.worst_pct;
  g.goal_met = !worst_failed && g.rms <= goals_.sigma.rms_pct;
  g.left_goal_at_s = g.goal_met ? -1 : worst_failed ? first_over_worst_s_ : first_over_rms_s_;
  if (!g.goal_met && g.left_goal_at_s < 0) g.left_goal_at_s = running_since_s_;
  judge(g, sigma_alarm_s_, goals_.alarm_within_s);

  LoopScore& c = r.clamp;
  clamp_.fill(c);
  c.above_ceiling_s = above_ceiling_s_;
  c.goal_met = above_ceiling_s_ == 0 && c.in_band_pct >= goals_.clamp.in_band_share_pct;
  if (!c.goal_met) {
    const double band_onset = clamp_.left_goal_at_s();
    c.left_goal_at_s = first_above_s_ >= 0 && (band_onset < 0 || first_above_s_ < band_onset)
                           ? first_above_s_
                           : band_onset;
  }
  judge(c, clamp_alarm_s_, goals_.alarm_within_s);

  LoopScore& d = r.depth;
  depth_.fill(d);
  d.goal_met = d.in_band_pct >= goals_.depth.in_band_share_pct;
  if (!d.goal_met) d.left_goal_at_s = depth_.left_goal_at_s();
  judge(d, depth_alarm_s_, goals_.alarm_within_s);
  return r;
}

namespace {

nlohmann::ordered_json score_json(const LoopScore& s) {
  return {{"rms", s.rms},
          {"worst", s.worst},
          {"in_band_pct", s.in_band_pct},
          {"longest_out_s", s.longest_out_s},
          {"left_goal_at_s", s.left_goal_at_s},
          {"alarm_at_s", s.alarm_at_s},
          {"above_ceiling_s", s.above_ceiling_s},
          {"goal_met", s.goal_met},
          {"verdict", verdict_name(s.verdict)}};
}

LoopScore score_from(const nlohmann::json& j) {
  LoopScore s;
  s.rms = j.at("rms").get<double>();
  s.worst = j.at("worst").get<double>();
  s.in_band_pct = j.at("in_band_pct").get<double>();
  s.longest_out_s = j.at("longest_out_s").get<double>();
  s.left_goal_at_s = j.at("left_goal_at_s").get<double>();
  s.alarm_at_s = j.at("alarm_at_s").get<double>();
  s.above_ceiling_s = j.at("above_ceiling_s").get<double>();
  s.goal_met = j.at("goal_met").get<bool>();
  const std::string v = j.at("verdict").get<std::string>();
  s.verdict = v == "held" ? Verdict::held : v == "alarmed" ? Verdict::alarmed : Verdict::silent;
  return s;
}

}  // namespace

std::string loop_score_json(const LoopScore& s) { return score_json(s).dump(); }

std::string loop_scores_json(const LoopScores& s) {
  nlohmann::ordered_json j;
  j["sigma"] = score_json(s.sigma);
  j["clamp"] = score_json(s.clamp);
  j["depth"] = score_json(s.depth);
  return j.dump();
}

LoopScores loop_scores_from_json(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  return {score_from(j.at("sigma")), score_from(j.at("clamp")), score_from(j.at("depth"))};
}

}  // namespace planter::sim
