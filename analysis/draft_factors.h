#pragma once
// The draft law's two costly factors along a recording (sim/soil/opener_draft.h), each kept
// for its last arguments: planter-fit runs the draft channel's simulation thousands of times,
// and a numeric Jacobian moves one parameter at a time. Only m moves the depth's power; only
// the speed's lag, the mobilisation travel and the relaxation time move the mobilised share;
// the draft's size moves neither. One cache per thread: channels are analysed on several.
#include <vector>

namespace planter::analysis {

// T_ref (d / T_ref)^m in cm at each row (draft_depth_cm_of_log).
const std::vector<double>& draft_depth_along(const std::vector<double>& depth_mm, double m);

// The mobilised share at each row (mobilised_share_after), from 0 at the first row, for the
// law's mobilisation travel and relaxation time: `v_mps` the forward speed, zero where the
// machine stands (`rest`); `t_s` the rows' times.
const std::vector<double>& draft_share_along(double mobilisation_mm, double rest_relaxation_s,
                                             const std::vector<double>& v_mps,
                                             const std::vector<bool>& rest,
                                             const std::vector<double>& t_s);

}  // namespace planter::analysis
