#pragma once
// How firmly the soil holds a seedling's buried root sideways: the root is a short rigid pile
// in a c-phi soil (friction angle phi, apparent cohesion c).
//
// The form: Broms' short pile ("Lateral resistance of piles in cohesionless soils", J. Soil
// Mech. Found. Div. ASCE 90(SM3), 1964) takes the ultimate soil pressure at depth z as three
// times Rankine's passive pressure, per unit width of the pile. With cohesion the passive
// pressure is Rankine-Bell's, K_p gamma z + 2 c sqrt(K_p) (Craig, "Soil Mechanics", ch. 11),
// K_p = tan^2(45 deg + phi / 2). So p_u(z) = 3 D (K_p gamma z + 2 c sqrt(K_p)) for a root of
// diameter D. (For c = 0 this is Broms' cohesionless pile exactly; the factor 3 on the cohesive
// part is this model's choice, below Broms' 9 c_u for deep clay, which needs a depth a 50 mm
// root does not have.) Over a buried length b:
//   plowing:  a root dragged sideways meets H = 1.5 K_p gamma D b^2 + 6 c sqrt(K_p) D b,
//   anchored: a free root turning about its end holds a moment up to
//             M_u = 0.5 K_p gamma D b^3 + 3 c sqrt(K_p) D b^2, and a sideways load at height e
//             above the surface up to H_u = M_u / (e + b).
// Rigid-plastic: below these the root does not move (the soil's elastic give, of the order of a
// millimetre for a root this size, is left out); at them it moves with the load.
#include <cmath>

namespace planter::soil {

// Values and sources: sim/plant/model_values.cpp (every one is assumed, with its range).
struct Soil {
  double unit_weight_kN_per_m3 = 14.0;  // gamma
  double friction_angle_deg = 30.0;     // phi
  double cohesion_kPa = 0.0;            // c, apparent (moist soil's suction)
};

inline double passive_coefficient(const Soil& s) {
  const double half = (45.0 + 0.5 * s.friction_angle_deg) * 3.14159265358979323846 / 180.0;
  const double t = std::tan(half);
  return t * t;
}

// The resistances of one soil, for a root of diameter d_m buried b_m.
class RootAnchorage {
 public:
  explicit RootAnchorage(const Soil& s)
      : kp_gamma_(passive_coefficient(s) * 1e3 * s.unit_weight_kN_per_m3),
        cohesive_Pa_(2.0 * 1e3 * s.cohesion_kPa * std::sqrt(passive_coefficient(s))) {}

  // Dragged sideways through the soil.
  [[nodiscard]] double plowing_force_N(double d_m, double b_m) const {
    return b_m > 0.0 ? 1.5 * kp_gamma_ * d_m * b_m * b_m + 3.0 * cohesive_Pa_ * d_m * b_m : 0.0;
  }
  // Depth below the surface at which the plowing force acts (its pressure's centroid).
  [[nodiscard]] double plowing_depth_m(double d_m, double b_m) const {
    const double h = plowing_force_N(d_m, b_m);
    if (h <= 0.0) return 0.0;
    // Triangle (friction) acts at 2b/3, rectangle (cohesion) at b/2.
    const double friction = 1.5 * kp_gamma_ * d_m * b_m * b_m;
    return (friction * 2.0 * b_m / 3.0 + (h - friction) * 0.5 * b_m) / h;
  }
  // The largest sideways load at height e_m above the surface the root holds.
  [[nodiscard]] double holding_force_N(double d_m, double b_m, double e_m) const {
    return b_m > 0.0 ? holding_moment_Nm(d_m, b_m) / (std::fmax(0.0, e_m) + b_m) : 0.0;
  }
  // The largest overturning moment about the root's end the soil holds.
  [[nodiscard]] double holding_moment_Nm(double d_m, double b_m) const {
    return b_m > 0.0
               ? 0.5 * kp_gamma_ * d_m * b_m * b_m * b_m + 1.5 * cohesive_Pa_ * d_m * b_m * b_m
               : 0.0;
  }

 private:
  double kp_gamma_;     // K_p gamma, N/m^3
  double cohesive_Pa_;  // 2 c sqrt(K_p), Pa
};

}  // namespace planter::soil
