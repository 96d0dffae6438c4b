#include "dem/platen_arrays.h"

namespace planter::dem {

void PlatenArrays::resize(std::size_t platens, const std::vector<PairProperties>& properties) {
  particles = properties.size();
  constants.resize(particles);
  for (std::size_t k = 0; k < particles; ++k) constants.set(k, properties[k]);
  const std::size_t n = platens * particles;
  for (auto* a : {&spring_x, &spring_y, &spring_z}) a->resize(n, 0.0);
  for (auto* a : {&fx, &fy, &fz, &tx, &ty, &tz, &normal_N, &near}) a->assign(n, 0.0);
}

}  // namespace planter::dem
