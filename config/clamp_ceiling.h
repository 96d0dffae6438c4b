#pragma once
// The clamp's ceiling, derived and not typed in (issue 50): the force through the nip at which a
// stated share of the stems pass their first peak, the point where the wall collapses (the
// paper's damage rule, Sec. 4: damaged once the force passes the measured peak).
//
// The strength is the paper's six measured peaks (config/stem_strength.h, lognormal). The test's
// plates loaded a specimen of some length L; the lips load the stem over its held length, contact
// area / diameter, at most the band of protrusions (the paper, Sec. 3.1 and 5). The wall gives at
// the same line load, so a stem of diameter d passes its peak through the nip at
//     P_nip(d) = P_test x held(d) / L,        held(d) = min(A / d, band).
// No measurement ties the peak to the diameter (the scenario's strength_diameter_exponent is 0 by
// default), so none is taken here. The ceiling is the share's quantile of P_nip at the reference
// stem (the one the clamp law is calibrated with); a thicker stem's own is lower by held(d), which
// the clamp loop applies per stem (firmware/control/clamp_force_loop.h). L is not given by the
// paper: assumed, and the ceiling scales with 1 / L (docs/control.md says what would settle it).
#include <string>

namespace planter::config {

struct ClampCeilingRule {
  double specimen_length_mm = 25.0;  // assumed (15-50 mm): the strength test's loaded length
  double stems_past_peak_pct = 1.0;  // the share of stems the ceiling lets pass their peak
  double contact_area_mm2 = 245.0;   // the lips' contact with a stem (the paper: 244.81 optimum)
  double band_mm = 40.0;             // the band of flexible protrusions (the paper, Sec. 5)
};

// The length of stem the lips hold (mm): contact area over diameter, at most the band.
[[nodiscard]] double held_length_mm(double contact_area_mm2, double band_mm, double diameter_mm);

// The standard normal quantile of a probability in (0, 1).
[[nodiscard]] double normal_quantile(double p);

// The force through the nip (N) at which the rule's share of stems of this diameter pass their
// first peak.
[[nodiscard]] double clamp_ceiling_N(const ClampCeilingRule& rule, double diameter_mm);

// One sentence: the ceiling at this diameter and how it follows from the rule.
[[nodiscard]] std::string clamp_ceiling_derivation(const ClampCeilingRule& rule,
                                                   double diameter_mm);

}  // namespace planter::config
