#pragma once
// The stem in the clamp's nip, read from the load cell and the roller (issue 50). The clamp law
// F = k (x - x0)^n holds the stem it was calibrated with; another stem moves the gap the law
// sees (sim/plant/clamp_nip.h): a thicker one closes it, a softer one opens it. So each tick
// the law's position for the measured force, less the roller's measured position, is what the
// stem in the nip adds to the law's compression (a disturbance observer: Ohnishi, Shibata and
// Murakami, "Motion control for advanced mechatronics", IEEE/ASME Trans. Mechatronics 1(1),
// 1996: the input disturbance from the plant's model and its measured output). What the lips
// themselves drift by (a stiffer batch, wear) changes slowly and is taken out as a baseline over
// many stems, which assumes the batch's mean stem is near the reference one. A collapse of a stem's
// wall (the DEM's first peak) opens the gap by about a millimetre between two ticks, faster than
// any stem comes under the roller at the disc's speeds here: that drop is counted as damage seen.

namespace planter {

struct StemReaderConfig {
  double reference_diameter_mm = 10.0;  // the stem the clamp law is calibrated with
  // The lips' added compression per mm of stem over the reference (assumed 0.25-1.0; the
  // simulator's plant takes the same declared value).
  double thickness_gain = 0.5;
  double baseline_tau_s = 5.0;  // the lips' own drift is slower than this; ten stems or more
  double filter_tau_s = 0.02;   // two ticks: the load cell's noise (1 N, 0.035 mm) smoothed
  // The reading is this old by the time the roller has moved on it: the load cell's path (two
  // ticks) and the roller's lag (0.05 s); the stem's rate carries it forward by as much.
  double lead_s = 0.07;
  // The rim's travel over which the lips close on a stem: the elastic roller's radius (the
  // paper, Sec. 2.2: a 20 mm roller). While a stem comes in, its reading rises for this long at
  // the rim's speed, so the stem as it will be once in is its reading now plus its rate over the
  // rest of that time: the loop knows a stem in its first ticks, not when it is in.
  double entry_mm = 10.0;
  double entry_horizon_max_s = 0.25;  // at a crawl, no further ahead than this
  // A rise slower than this is the load cell's noise (1 N a tick is some 2 mm/s after the
  // filter), not a stem coming in: a 0.5 mm stem comes in at 4 mm/s at the paper's speed.
  double entry_rate_min_mm_per_s = 3.0;
  // A drop of the added compression between ticks beyond this is a wall giving way: a collapse
  // opens the gap by 1.1-1.3 mm, a stem coming in or out moves it at most 0.22 mm a tick at
  // the paper's 0.278 rad/s (the simulator's field run), 0.8 mm at the disc's top 1.2 rad/s.
  double collapse_mm = 0.6;
};

class StemReader {
 public:
  explicit StemReader(const StemReaderConfig& config) : cfg_(config) {}

  void reset();  // the nip opened: the next reading starts afresh (the baseline is kept)
  // `added_mm`: the law's position for the measured force less the roller's, this tick.
  void update(double added_mm, double dt_s);

  // What the stem in the nip adds now (filtered, baseline taken out), and its diameter by it.
  [[nodiscard]] double stem_mm() const { return stem_mm_; }
  // The same carried forward by lead_s at its present rate: what the feed-forward takes.
  [[nodiscard]] double stem_ahead_mm() const { return stem_mm_ + cfg_.lead_s * rate_mm_per_s_; }
  // The stem once it is in (entry_mm) at the rim's speed now, and its diameter by that.
  [[nodiscard]] double stem_in_mm(double rim_speed_mm_per_s) const;
  [[nodiscard]] double diameter_mm(double rim_speed_mm_per_s) const {
    return cfg_.reference_diameter_mm + stem_in_mm(rim_speed_mm_per_s) / cfg_.thickness_gain;
  }
  [[nodiscard]] long collapses() const { return collapses_; }
  // The baseline has had two of its time constants to find the lips' own reading: before that
  // a stem cannot be told from the lips (or from a load cell's error).
  [[nodiscard]] bool settled() const { return read_s_ >= 2.0 * cfg_.baseline_tau_s; }
  [[nodiscard]] const StemReaderConfig& config() const { return cfg_; }

 private:
  StemReaderConfig cfg_;
  double baseline_mm_ = 0.0;
  double stem_mm_ = 0.0;
  double rate_mm_per_s_ = 0.0;
  double last_added_mm_ = 0.0;
  bool has_last_ = false, has_baseline_ = false;
  long collapses_ = 0;
  double read_s_ = 0.0;  // time read since the baseline's start
};

}  // namespace planter
