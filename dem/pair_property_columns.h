#pragma once
// Hertz-Mindlin pair constants (PairProperties) as columns, one row per pair: what the contact
// lanes read, for the candidate pairs (dem/contact_arrays.h) and the particles against the
// platens (dem/platen_arrays.h).
#include <cstddef>
#include <vector>

#include "dem/hertz_mindlin.h"

namespace planter::dem {

struct PairPropertyColumns {
  std::vector<double> e_star, g_star, r_star, m_star, beta, shear_to_normal_root;

  [[nodiscard]] std::size_t size() const { return e_star.size(); }
  void resize(std::size_t rows);
  void set(std::size_t row, const PairProperties& p);
  [[nodiscard]] PairProperties at(std::size_t row) const;
};

}  // namespace planter::dem
