// The reference path: one bond at a time. Built with the vectoriser off (dem/CMakeLists.txt),
// so that it is the scalar arithmetic the vector paths are held to.
#include "dem/bond_kernel_paths.h"
#include "dem/bond_lane.h"

namespace planter::dem::lanes {

BondView view(BondArrays& b) {
  return {b.i.data(),
          b.j.data(),
          b.normal_force_N.data(),
          b.twist_moment.data(),
          b.shear_x.data(),
          b.shear_y.data(),
          b.shear_z.data(),
          b.bending_x.data(),
          b.bending_y.data(),
          b.bending_z.data(),
          b.broken.data(),
          b.force_on_j_x.data(),
          b.force_on_j_y.data(),
          b.force_on_j_z.data(),
          b.torque_on_i_x.data(),
          b.torque_on_i_y.data(),
          b.torque_on_i_z.data(),
          b.torque_on_j_x.data(),
          b.torque_on_j_y.data(),
          b.torque_on_j_z.data(),
          b.loaded.data()};
}

MotionView view(const ParticleMotion& m) {
  return {m.x.data(),  m.y.data(),  m.z.data(),  m.vx.data(), m.vy.data(),
          m.vz.data(), m.wx.data(), m.wy.data(), m.wz.data(), m.radius_m.data()};
}

void bonds_scalar(const BondView& b, const MotionView& m, const BondStep& s, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) bond_lane(b, m, s, k);
}

}  // namespace planter::dem::lanes
