#pragma once
// The bonded-particle world: particles, parallel bonds, Hertz-Mindlin contacts (between
// particles and with rigid platens), integrated with the symplectic (leapfrog) Euler step.
// Single-threaded and deterministic: the same input gives bit-identical results.
#include <map>
#include <utility>
#include <vector>

#include "sim/dem/cell_list.h"
#include "sim/dem/hertz_mindlin.h"
#include "sim/dem/parallel_bond.h"

namespace planter::dem {

// A rigid plane that pushes particles on its positive side: point, outward normal, velocity.
struct Platen {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  Vec3 velocity = Vec3::Zero();
  double force_N = 0.0;  // normal force the particles put on it this step
};

class DemWorld {
 public:
  DemWorld(const ContactMaterial& material, const BondParameters& bonds)
      : material_(material), bond_params_(bonds) {}

  int add_particle(const Particle& p);
  // Bonds every pair whose surfaces are within `gap_m` of touching.
  int bond_neighbours(double gap_m);
  void add_bond(int i, int j);
  int add_platen(const Platen& p);

  void step(double dt);

  [[nodiscard]] std::vector<Particle>& particles() { return particles_; }
  [[nodiscard]] const std::vector<Particle>& particles() const { return particles_; }
  [[nodiscard]] const std::vector<Bond>& bonds() const { return bonds_; }
  [[nodiscard]] std::vector<Platen>& platens() { return platens_; }
  [[nodiscard]] int broken_bonds() const;
  [[nodiscard]] double kinetic_energy() const;
  [[nodiscard]] double bond_energy() const;
  // Elastic energy in particle-particle overlaps (a diagnostic: all pairs, O(n^2)).
  [[nodiscard]] double contact_energy() const;
  [[nodiscard]] long steps() const { return steps_; }

 private:
  void contacts(double dt);
  ContactMaterial material_;
  BondParameters bond_params_;
  std::vector<Particle> particles_;
  std::vector<Bond> bonds_;
  std::vector<Platen> platens_;
  CellList cells_;
  std::vector<std::pair<int, int>> candidates_;
  std::map<std::pair<int, int>, Vec3> springs_;         // particle-particle history
  std::map<std::pair<int, int>, Vec3> platen_springs_;  // (platen, particle) history
  long steps_ = 0;
};

}  // namespace planter::dem
