#include "firmware/sensing/ground_fusion.h"

#include <algorithm>
#include <cmath>

namespace planter {

namespace {
constexpr double kDegToRad = 0.017453292519943295;
// The heading's memory, in fixes: about 30 s at 10 Hz, so a turn at the headland is
// forgotten within a row's first metres (assumed).
constexpr double kHeadingMemoryFixes = 300.0;
// Fixes summed before the heading is trusted: the first fix alone would define it.
constexpr double kHeadingMinFixes = 10.0;
}  // namespace

const char* gnss_use_name(GnssUse use) {
  switch (use) {
    case GnssUse::kNone:
      return "no receiver";
    case GnssUse::kUsing:
      return "in use";
    case GnssUse::kNoFix:
      return "no fix";
    case GnssUse::kPoorFix:
      return "poor fix";
    case GnssUse::kStale:
      return "no new fix";
    case GnssUse::kRefused:
      return "speed refused";
    case GnssUse::kDisconnected:
      return "receiver not connected";
  }
  return "";
}

GroundFusion::GroundFusion(const GroundFusionConfig& config)
    : cfg_(config),
      p_(config.scale_start_sd * config.scale_start_sd),
      use_(config.gnss_fitted ? GnssUse::kNoFix : GnssUse::kNone) {}

double GroundFusion::scale_sd() const { return std::sqrt(p_); }

void GroundFusion::remember(std::int64_t now_ns, double wheel_m) {
  history_[head_] = {now_ns, wheel_m};
  head_ = (head_ + 1) % kHistory;
  filled_ = std::min(filled_ + 1, kHistory);
}

bool GroundFusion::wheel_at(std::int64_t t_ns, double& wheel_m) const {
  if (filled_ == 0) return false;
  const WheelSample* newer = &history_[(head_ + kHistory - 1) % kHistory];
  if (t_ns > newer->t_ns) return false;
  for (std::size_t i = 2; i <= filled_; ++i) {
    const WheelSample& older = history_[(head_ + kHistory - i) % kHistory];
    if (older.t_ns <= t_ns) {
      const double span = static_cast<double>(newer->t_ns - older.t_ns);
      const double f = span > 0 ? static_cast<double>(t_ns - older.t_ns) / span : 1.0;
      wheel_m = older.wheel_m + f * (newer->wheel_m - older.wheel_m);
      return true;
    }
    newer = &older;
  }
  return false;
}

void GroundFusion::set_estimate(double k, double wheel_now_m) {
  k_est_ = std::clamp(k, 0.5, 2.0);
  const double beyond = std::abs(k_est_ - 1.0) - cfg_.apply_beyond_sd * std::sqrt(p_);
  const double applied = beyond > 0 ? 1.0 + std::copysign(beyond, k_est_ - 1.0) : 1.0;
  anchor_ground_m_ = ground_m(wheel_now_m);
  anchor_wheel_m_ = wheel_now_m;
  k_ = applied;
}

GnssUse judge_fix(const GroundFusionConfig& cfg, const hal::GnssFix& fix,
                  std::int64_t last_fix_ns) {
  if (!hal::has_position(fix)) return GnssUse::kNoFix;
  if (!std::isfinite(fix.speed_mps) || !std::isfinite(fix.track_deg) || fix.speed_mps < 0 ||
      fix.speed_mps > cfg.max_speed_mps) {
    return GnssUse::kRefused;
  }
  if ((fix.satellites > 0 && fix.satellites < cfg.min_satellites) ||
      (fix.hdop > 0 && fix.hdop > cfg.max_hdop) ||
      (fix.speed_err_mps > 0 && fix.speed_err_mps > cfg.max_speed_err_mps) ||
      !std::isfinite(fix.hdop) || !std::isfinite(fix.speed_err_mps)) {
    return GnssUse::kPoorFix;
  }
  // A time that stands still or runs back is a receiver (or a log) that stopped.
  if (last_fix_ns != 0 && fix.valid_ns <= last_fix_ns) return GnssUse::kStale;
  return GnssUse::kUsing;
}

// Measures k from one fix's speed along the row against the wheel's over the same interval.
void GroundFusion::take(const hal::GnssFix& fix) {
  const double north = fix.speed_mps * std::cos(fix.track_deg * kDegToRad);
  const double east = fix.speed_mps * std::sin(fix.track_deg * kDegToRad);
  const double n_fixes = static_cast<double>(used_);
  const double norm = std::hypot(sum_north_, sum_east_);
  const bool heading_known = n_fixes >= kHeadingMinFixes && norm > 0;
  along_row_mps_ = heading_known ? (north * sum_north_ + east * sum_east_) / norm : 0.0;
  const double keep = 1.0 - 1.0 / kHeadingMemoryFixes;
  sum_north_ = sum_north_ * keep + north;
  sum_east_ = sum_east_ * keep + east;
  const std::int64_t epoch_ns = std::clamp<std::int64_t>(
      last_fix_ns_ ? fix.valid_ns - last_fix_ns_ : 100'000'000, 50'000'000, 1'000'000'000);
  last_fix_ns_ = fix.valid_ns;
  ++used_;
  double w1 = 0, w0 = 0;
  if (!heading_known || !wheel_at(fix.valid_ns, w1) || !wheel_at(fix.valid_ns - epoch_ns, w0))
    return;
  const double v_wheel = (w1 - w0) / (static_cast<double>(epoch_ns) * 1e-9);
  const double err = fix.speed_err_mps > 0 ? fix.speed_err_mps : cfg_.default_speed_err_mps;
  const double s = v_wheel * v_wheel * p_ + err * err;
  const double innovation = along_row_mps_ - k_est_ * v_wheel;
  if (std::abs(innovation) > cfg_.gate_sigma * std::sqrt(s)) {
    ++refused_;
    return;
  }
  const double gain = p_ * v_wheel / s;
  p_ *= 1.0 - gain * v_wheel;
  set_estimate(k_est_ + gain * innovation, last_wheel_m_);
}

void GroundFusion::update(const MachineState& in, std::int64_t now_ns) {
  remember(now_ns, in.distance_m);
  const double moved = std::abs(in.distance_m - last_wheel_m_);
  last_wheel_m_ = in.distance_m;
  p_ += cfg_.scale_walk_per_sqrt_m * cfg_.scale_walk_per_sqrt_m * moved;
  // The threshold widens with the variance as the wheel rolls without a fix.
  if (moved > 0 && k_ != 1.0) set_estimate(k_est_, in.distance_m);
  if (cfg_.gnss_fitted) {
    GnssUse why = use_ == GnssUse::kUsing ? GnssUse::kStale : use_;
    if (!in.gnss_connected) {
      why = GnssUse::kDisconnected;
    } else if (in.gnss.sequence != 0 && in.gnss.sequence != last_seq_) {
      last_seq_ = in.gnss.sequence;
      const GnssUse judged = judge_fix(cfg_, in.gnss, last_fix_ns_);
      const double age_s = static_cast<double>(now_ns - in.gnss.valid_ns) * 1e-9;
      if (judged == GnssUse::kUsing && age_s <= cfg_.fix_timeout_s && age_s >= 0) {
        const std::uint64_t refused_before = refused_;
        take(in.gnss);
        if (refused_ == refused_before) {
          last_usable_ns_ = now_ns;
          ever_usable_ = true;
        } else {
          why = GnssUse::kRefused;
        }
      } else {
        why = judged == GnssUse::kUsing ? GnssUse::kStale : judged;
      }
    }
    const bool fresh = ever_usable_ && in.gnss_connected &&
                       static_cast<double>(now_ns - last_usable_ns_) * 1e-9 <= cfg_.fix_timeout_s;
    use_ = fresh ? GnssUse::kUsing : why;
  }
  distance_m_ = ground_m(in.distance_m);
  speed_mps_ = k_ * in.v_wheel_mps;
}

}  // namespace planter
