#pragma once
// The load cell's zero, taken while the lips are open: with the roller short of the lips'
// contact the true force is nil, so what the cell reads is its offset (and the drift so far).
// Weighing instruments zero themselves the same way at a known empty load (OIML R 76-1's
// zero-setting device). It runs in the ready state and in the first zero_s of each run, when
// the controller holds the lips open for it; never while commissioning (a test weight may
// hang there). The offset taken is bounded: a larger one is a fault to fix, not to hide.

namespace planter {

struct LoadCellZeroConfig {
  double zero_s = 0.3;               // the lips held open this long at each start
  double max_offset_N = 10.0;        // assumed: a ninth of the set-point at most is taken
  double clear_of_contact_mm = 0.5;  // the roller this far short of contact counts as open
};

class LoadCellZero {
 public:
  explicit LoadCellZero(const LoadCellZeroConfig& config) : cfg_(config) {}
  // One tick: `open` while the lips are known open. Each open stretch's mean is the zero.
  void update(double reading_N, bool open);
  [[nodiscard]] double corrected_N(double reading_N) const { return reading_N - offset_N_; }
  [[nodiscard]] double offset_N() const { return offset_N_; }
  [[nodiscard]] const LoadCellZeroConfig& config() const { return cfg_; }

 private:
  LoadCellZeroConfig cfg_;
  double offset_N_ = 0.0;
  double sum_N_ = 0.0;
  int samples_ = 0;  // in this open stretch (0: closed)
};

}  // namespace planter
