#pragma once
// The parallel bonds as a structure of arrays, and the particles' motion the bond step reads,
// so that one bond per vector lane is computed (dem/bond_kernel.h). Flags are doubles (0 or 1)
// to keep every lane one width.
#include <cstddef>
#include <vector>

#include "dem/incidence.h"
#include "dem/parallel_bond.h"

namespace planter::dem {

struct BondArrays {
  // The pair and its as-built overlap.
  std::vector<int> i, j;
  std::vector<double> rest_overlap_m;
  // The loads carried from step to step (Bond's fields, one array per component).
  std::vector<double> normal_force_N, twist_moment;
  std::vector<double> shear_x, shear_y, shear_z;
  std::vector<double> bending_x, bending_y, bending_z;
  std::vector<double> broken;
  // This step's loads on the particles, and whether the bond carried any (1) or not (0).
  std::vector<double> force_on_j_x, force_on_j_y, force_on_j_z;
  std::vector<double> torque_on_i_x, torque_on_i_y, torque_on_i_z;
  std::vector<double> torque_on_j_x, torque_on_j_y, torque_on_j_z;
  std::vector<double> loaded;

  [[nodiscard]] std::size_t size() const { return i.size(); }
  void push_back(const Bond& b);
  [[nodiscard]] Bond bond(std::size_t k) const;
};

// Position, velocity, angular velocity and radius of every particle, one array per component,
// and 1/|w| (0 for a particle that does not spin).
struct ParticleMotion {
  std::vector<double> x, y, z, vx, vy, vz, wx, wy, wz, radius_m, inv_spin;
  void assign(const std::vector<Particle>& particles);
};

// Adds bond k's loads on its j (`on_j`) or its i to `particle` (nothing if it carried none).
void add_bond_load(const BondArrays& bonds, std::size_t k, bool on_j, Particle& particle);
// Adds the loads of each bond particle `p` is in to `particle`, in bond order (the order is the
// result's: floating-point sums are not associative). `bonds_of` is the bonds' incidence.
void add_bond_loads(const BondArrays& bonds, const Incidence& bonds_of, std::size_t p,
                    Particle& particle);
// The same sums for every particle at once, in one pass over the bonds (one thread: the
// arrays are read in order).
void add_all_bond_loads(const BondArrays& bonds, std::vector<Particle>& particles);

}  // namespace planter::dem
