#pragma once
// How firmly the soil holds a seedling's buried root sideways: the root is a short rigid pile
// in cohesionless (tilled, loose) soil, after Broms, "Lateral resistance of piles in
// cohesionless soils", J. Soil Mech. Found. Div. ASCE 90(SM3), 1964. The ultimate soil pressure
// at depth z is 3 K_p gamma z per unit width of the pile (Broms' simplification), K_p Rankine's
// passive coefficient tan^2(45 deg + phi / 2) (Craig, "Soil Mechanics", ch. 11). Over a buried
// length b and diameter D this gives:
//   plowed:  a root dragged sideways through the soil meets H = 1.5 K_p gamma D b^2,
//            acting b / 3 above its end;
//   anchored: a free root turned by a sideways load at height e above the surface holds up to
//            H_u = 0.5 gamma D b^3 K_p / (e + b), and a moment about its end up to
//            M_u = 0.5 K_p gamma D b^3.
// Rigid-plastic: below these the root does not move (the soil's elastic give, of the order of a
// millimetre for a root this size, is left out); at them it moves with the load.
#include <cmath>

namespace planter::soil {

struct CohesionlessSoil {
  double unit_weight_N_per_m3 = 14000.0;  // gamma: loose tilled loam, about 1.4 t/m^3 (assumed)
  double friction_angle_deg = 30.0;       // phi: loose loam (assumed)
};

inline double passive_coefficient(const CohesionlessSoil& s) {
  const double half = (45.0 + 0.5 * s.friction_angle_deg) * 3.14159265358979323846 / 180.0;
  const double t = std::tan(half);
  return t * t;
}

// The three resistances of one soil, for a root of diameter d_m buried b_m.
class RootAnchorage {
 public:
  explicit RootAnchorage(const CohesionlessSoil& s)
      : kp_gamma_(passive_coefficient(s) * s.unit_weight_N_per_m3) {}

  // Dragged sideways through the soil.
  [[nodiscard]] double plowing_force_N(double d_m, double b_m) const {
    return b_m > 0.0 ? 1.5 * kp_gamma_ * d_m * b_m * b_m : 0.0;
  }
  // The largest sideways load at height e_m above the surface the root holds.
  [[nodiscard]] double holding_force_N(double d_m, double b_m, double e_m) const {
    return b_m > 0.0 ? holding_moment_Nm(d_m, b_m) / (std::fmax(0.0, e_m) + b_m) : 0.0;
  }
  // The largest overturning moment about the root's end the soil holds.
  [[nodiscard]] double holding_moment_Nm(double d_m, double b_m) const {
    return b_m > 0.0 ? 0.5 * kp_gamma_ * d_m * b_m * b_m * b_m : 0.0;
  }

 private:
  double kp_gamma_;  // K_p gamma, N/m^3
};

}  // namespace planter::soil
