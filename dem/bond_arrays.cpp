#include "dem/bond_arrays.h"

namespace planter::dem {

void BondArrays::push_back(const Bond& b) {
  i.push_back(b.i);
  j.push_back(b.j);
  rest_overlap_m.push_back(b.rest_overlap_m);
  normal_force_N.push_back(b.normal_force_N);
  twist_moment.push_back(b.twist_moment);
  shear_x.push_back(b.shear_force.x());
  shear_y.push_back(b.shear_force.y());
  shear_z.push_back(b.shear_force.z());
  bending_x.push_back(b.bending_moment.x());
  bending_y.push_back(b.bending_moment.y());
  bending_z.push_back(b.bending_moment.z());
  broken.push_back(b.broken ? 1.0 : 0.0);
  loads.resize(i.size());
}

Bond BondArrays::bond(std::size_t k) const {
  Bond b;
  b.i = i[k];
  b.j = j[k];
  b.rest_overlap_m = rest_overlap_m[k];
  b.normal_force_N = normal_force_N[k];
  b.twist_moment = twist_moment[k];
  b.shear_force = Vec3(shear_x[k], shear_y[k], shear_z[k]);
  b.bending_moment = Vec3(bending_x[k], bending_y[k], bending_z[k]);
  b.broken = broken[k] != 0.0;
  return b;
}

}  // namespace planter::dem
