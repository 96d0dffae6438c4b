#pragma once
// The candidate pairs of the Verlet list as a structure of arrays (one pair per vector lane in
// dem/contact_kernel.h): the pair, its Hertz-Mindlin constants, its contact history, and this
// step's loads. Flags are doubles (0 or 1) to keep every lane one width.
#include <cstddef>
#include <vector>

#include "dem/hertz_mindlin.h"
#include "dem/incidence.h"

namespace planter::dem {

struct ContactArrays {
  std::vector<int> i, j;
  std::vector<int> bond;               // index into the bonds for a pair bonded at build, or -1
  std::vector<double> rest_overlap_m;  // the bonded pair's as-built overlap, else 0
  std::vector<double> e_star, g_star, r_star, m_star, beta, shear_to_normal_root;  // PairProperties
  std::vector<double> spring_x, spring_y, spring_z;  // tangential spring (history)
  // This step's loads, and whether the pair touched (1) or not (0).
  std::vector<double> force_on_i_x, force_on_i_y, force_on_i_z;
  std::vector<double> torque_on_i_x, torque_on_i_y, torque_on_i_z;
  std::vector<double> torque_on_j_x, torque_on_j_y, torque_on_j_z;
  std::vector<double> touching;

  [[nodiscard]] std::size_t size() const { return i.size(); }
  void clear();
  void push_back(int pi, int pj, int bond_index, double rest_overlap, const PairProperties& p,
                 const Vec3& spring);
  [[nodiscard]] PairProperties properties(std::size_t k) const;
  [[nodiscard]] Vec3 spring(std::size_t k) const;
};

// Adds pair k's loads on its j (`on_j`) or its i to `particle` (nothing if it did not touch).
void add_contact_load(const ContactArrays& contacts, std::size_t k, bool on_j, Particle& particle);
// Adds the loads of each pair particle `p` is in to `particle`, in pair order (the order is
// the result's). `contacts_of` is the pairs' incidence.
void add_contact_loads(const ContactArrays& contacts, const Incidence& contacts_of, std::size_t p,
                       Particle& particle);
// The same sums for every particle at once, in one pass over the pairs.
void add_all_contact_loads(const ContactArrays& contacts, std::vector<Particle>& particles);

}  // namespace planter::dem
