#pragma once
// The bonded-particle world: particles, parallel bonds, Hertz-Mindlin contacts (between
// particles and with rigid platens), integrated with the symplectic (leapfrog) Euler step.
// Deterministic: the same input gives bit-identical results on every vector path of the bonds'
// and contacts' steps (dem/vector_path.h) and on any number of threads (set_threads).
#include <optional>
#include <utility>
#include <vector>

#include "dem/bond_arrays.h"
#include "dem/bond_kernel.h"
#include "dem/cell_list.h"
#include "dem/contact_kernel.h"
#include "dem/hertz_mindlin.h"
#include "dem/parallel_bond.h"
#include "dem/particle_motion.h"
#include "dem/step_threads.h"

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
  // `platen_material` is the platen's (the steel fixture in the paper): its elastic values,
  // and the particle-platen restitution and friction. By default the particles' own.
  DemWorld(const ContactMaterial& material, const BondParameters& bonds)
      : DemWorld(material, bonds, material) {}
  DemWorld(const ContactMaterial& material, const BondParameters& bonds,
           const ContactMaterial& platen_material)
      : material_(material), platen_material_(platen_material), bond_params_(bonds) {}

  int add_particle(const Particle& p);
  // Bonds every pair whose centres are within (r_i + r_j) + `gap_m`.
  int bond_neighbours(double gap_m);
  void add_bond(int i, int j);
  int add_platen(const Platen& p);
  // Cundall's local non-viscous damping (Yade's NewtonIntegrator damping): each force and
  // torque component is reduced by `fraction` of its size against the motion. 0 = none.
  void set_local_damping(double fraction) { local_damping_ = fraction; }
  // The vector path of the bonds' and contacts' steps: the widest this CPU has unless told
  // (the tests run each).
  void set_vector_path(VectorPath path) { vector_path_ = path; }
  [[nodiscard]] VectorPath vector_path() const { return vector_path_; }
  // Threads sharing each step's bonds and contacts (1: the calling thread alone, the default: a
  // calibration runs one world a core). The results are the same bits on any number.
  void set_threads(int threads) {
    threads_.reset();
    threads_.emplace(threads);
  }

  void step(double dt);

  [[nodiscard]] std::vector<Particle>& particles() { return particles_; }
  [[nodiscard]] const std::vector<Particle>& particles() const { return particles_; }
  // Every bond as it stands (a copy out of the bond arrays).
  [[nodiscard]] std::vector<Bond> bonds() const;
  [[nodiscard]] std::vector<Platen>& platens() { return platens_; }
  [[nodiscard]] int broken_bonds() const;
  [[nodiscard]] double kinetic_energy() const;
  [[nodiscard]] double bond_energy() const;
  // Elastic energy in particle-particle overlaps of unbonded pairs (a diagnostic, O(n^2)).
  [[nodiscard]] double contact_energy() const;
  [[nodiscard]] long steps() const { return steps_; }
  [[nodiscard]] long neighbour_rebuilds() const { return rebuilds_; }

 private:
  void rebuild_neighbours();
  [[nodiscard]] bool neighbours_stale() const;
  // Particle i's pair loads summed (`sum_pairs`; else they were), its platen contacts, and its
  // motion advanced.
  void particle_step(std::size_t i, bool sum_pairs, double dt);
  // Particle i's platen loads (update_platen_contacts left them), added after its pairs'.
  void add_platen_loads(std::size_t i, Particle& p) const;
  void integrate(Particle& p, double dt) const;

  ContactMaterial material_;
  ContactMaterial platen_material_;
  BondParameters bond_params_;
  std::vector<Particle> particles_;
  BondArrays bonds_;
  ParticleMotion motion_;  // the particles' motion as the pair steps read it
  VectorPath vector_path_ = widest_vector_path();
  std::optional<StepThreads> threads_{std::in_place, 1};
  std::vector<Platen> platens_;
  double local_damping_ = 0.0;
  // Verlet list: pairs within 2 r_max + skin; rebuilt when any particle has moved skin/2.
  CellList cells_;
  std::vector<std::pair<int, int>> pairs_scratch_;
  ContactArrays candidates_;  // the Verlet list's pairs and their contact history
  ContactArrays previous_;
  Incidence bonds_of_;     // the bonds each particle is in
  Incidence contacts_of_;  // the candidate pairs each particle is in
  std::vector<Vec3> x_at_rebuild_;
  double skin_m_ = 0.0;
  bool neighbours_valid_ = false;
  PlatenArrays platen_contacts_;  // every particle against every platen
  long steps_ = 0;
  long rebuilds_ = 0;
};

}  // namespace planter::dem
