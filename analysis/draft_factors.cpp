#include "analysis/draft_factors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "analysis/recent_two.h"
#include "sim/soil/opener_draft.h"

namespace planter::analysis {

const std::vector<double>& draft_depth_along(const std::vector<double>& depth_mm, double m) {
  struct Power {
    double m = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> depth_cm;
  };
  struct Cache {
    std::vector<double> depth_mm, log_ratio;
    std::array<Power, 2> powers;
  };
  thread_local Cache c;
  if (!same_bits(depth_mm, c.depth_mm)) {
    c.depth_mm = depth_mm;
    c.log_ratio.resize(depth_mm.size());
    // ln(d / T_ref), -inf at or above the surface (its power is then 0).
    for (std::size_t k = 0; k < depth_mm.size(); ++k)
      c.log_ratio[k] = std::log(std::max(0.0, depth_mm[k]) / soil::kDraftReferenceDepth_mm);
    for (Power& p : c.powers) p.m = std::numeric_limits<double>::quiet_NaN();
  }
  return recent_two(
             c.powers, [&](const Power& p) { return p.m == m; },
             [&](Power& p) {
               p.m = m;
               p.depth_cm.resize(c.log_ratio.size());
               for (std::size_t k = 0; k < c.log_ratio.size(); ++k)
                 p.depth_cm[k] = soil::draft_depth_cm_of_log(c.log_ratio[k], m);
             })
      .depth_cm;
}

const std::vector<double>& draft_share_along(double mobilisation_mm, double rest_relaxation_s,
                                             const std::vector<double>& v_mps,
                                             const std::vector<bool>& rest,
                                             const std::vector<double>& t_s) {
  struct Slot {
    double mobilisation_mm = std::numeric_limits<double>::quiet_NaN();
    double rest_relaxation_s = mobilisation_mm;
    std::vector<double> v_mps, t_s, share;
    std::vector<bool> rest;
  };
  thread_local std::array<Slot, 2> slots;
  soil::OpenerDraftLaw law;
  law.mobilisation_mm = mobilisation_mm;
  law.rest_relaxation_s = rest_relaxation_s;
  auto matches = [&](const Slot& s) {
    return s.mobilisation_mm == law.mobilisation_mm &&
           s.rest_relaxation_s == law.rest_relaxation_s && same_bits(s.v_mps, v_mps) &&
           s.rest == rest && same_bits(s.t_s, t_s);
  };
  auto fill = [&](Slot& s) {
    s.mobilisation_mm = law.mobilisation_mm;
    s.rest_relaxation_s = law.rest_relaxation_s;
    s.v_mps = v_mps;
    s.rest = rest;
    s.t_s = t_s;
    s.share.assign(v_mps.size(), 0.0);
    // The rest decay once per distinct step (the rows are evenly sampled).
    double decay_dt = -1.0, decay = 1.0, share = 0.0;
    for (std::size_t k = 1; k < v_mps.size(); ++k) {
      const double dt = t_s[k] - t_s[k - 1];
      if (dt != decay_dt) {
        decay_dt = dt;
        decay = soil::rest_decay(law, dt);
      }
      const double v_k = rest[k] ? 0.0 : v_mps[k];
      const double v_prev = rest[k - 1] ? 0.0 : v_mps[k - 1];
      share = soil::mobilised_share_after(law, share, 0.5 * (v_k + v_prev) * dt, decay);
      s.share[k] = share;
    }
  };
  return recent_two(slots, matches, fill).share;
}

}  // namespace planter::analysis
