#pragma once
// Contact and bond parameters of the seedling model (the paper's names in comments).
namespace planter::dem {

struct ContactMaterial {
  double shear_modulus_Pa = 2.62e6;  // G
  double poisson = 0.38;             // v
  double restitution = 0.5;          // e (particle-particle)
  double friction = 0.5;             // mu_s
  double rolling_friction = 0.01;    // mu_r (EDEM type A)
  [[nodiscard]] double youngs_modulus_Pa() const {
    return 2.0 * shear_modulus_Pa * (1.0 + poisson);
  }
};

struct BondParameters {
  double normal_stiffness_N_m3 = 4.842e9;  // S_n, per unit area
  double shear_stiffness_N_m3 = 4.842e9;   // S_t
  double tensile_strength_Pa = 5.643e7;    // sigma_c
  double shear_strength_Pa = 5.643e7;      // tau_c
  double radius_m = 2.0e-3;                // R_B
};

}  // namespace planter::dem
