#include "firmware/sensing/quadrature_decoder.h"

namespace planter {
namespace {
// Gray sequence 00 -> 01 -> 11 -> 10 is forward (A leads B).
int gray_index(bool a, bool b) { return a ? (b ? 2 : 3) : (b ? 1 : 0); }
}  // namespace

void QuadratureDecoder::on_edge(const hal::GpioEdge& edge) {
  if (edge.line > 1) return;
  bool& level = edge.line == 0 ? a_ : b_;
  if (level == edge.rising) {
    // A repeated level: an edge was lost or this is noise. Count it; do not move.
    ++invalid_;
    return;
  }
  if (edge.time_ns - last_edge_ns_[edge.line] < glitch_ns_) {
    // Too soon after the previous edge on this line: a glitch (and its partner edge will
    // restore the level, so follow the level without counting).
    ++glitches_;
    level = edge.rising;
    last_edge_ns_[edge.line] = edge.time_ns;
    return;
  }
  last_edge_ns_[edge.line] = edge.time_ns;
  const int before = gray_index(a_, b_);
  level = edge.rising;
  const int after = gray_index(a_, b_);
  const int step = (after - before + 4) % 4;
  if (step == 1) {
    ++count_;
    direction_ = 1;
  } else if (step == 3) {
    --count_;
    direction_ = -1;
  } else {
    ++invalid_;
    return;
  }
  last_count_ns_ = edge.time_ns;
}

}  // namespace planter
