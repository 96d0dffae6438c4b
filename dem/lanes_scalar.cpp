// The reference path: one pair at a time. Built with the vectoriser off (dem/CMakeLists.txt),
// so that it is the scalar arithmetic the vector paths are held to.
#include "dem/bond_lane.h"
#include "dem/contact_lane.h"
#include "dem/lane_paths.h"

namespace planter::dem::lanes {
namespace {

LoadsView loads_view(PairLoads& l) {
  return {l.force_on_i_x.data(),  l.force_on_i_y.data(),  l.force_on_i_z.data(),
          l.torque_on_i_x.data(), l.torque_on_i_y.data(), l.torque_on_i_z.data(),
          l.torque_on_j_x.data(), l.torque_on_j_y.data(), l.torque_on_j_z.data(),
          l.carried.data()};
}

}  // namespace

BondView view(BondArrays& b) {
  return {b.i.data(),         b.j.data(),         b.normal_force_N.data(), b.twist_moment.data(),
          b.shear_x.data(),   b.shear_y.data(),   b.shear_z.data(),        b.bending_x.data(),
          b.bending_y.data(), b.bending_z.data(), b.broken.data(),         loads_view(b.loads)};
}

ContactView view(ContactArrays& c) {
  return {c.i.data(),        c.j.data(),        c.rest_overlap_m.data(), view(c.constants),
          c.spring_x.data(), c.spring_y.data(), c.spring_z.data(),       loads_view(c.loads)};
}

PropertiesView view(const PairPropertyColumns& c) {
  return {c.e_star.data(), c.g_star.data(), c.r_star.data(),
          c.m_star.data(), c.beta.data(),   c.shear_to_normal_root.data()};
}

MotionView view(const ParticleMotion& m) {
  return {m.x.data(),  m.y.data(),        m.z.data(),        m.vx.data(),
          m.vy.data(), m.vz.data(),       m.wx.data(),       m.wy.data(),
          m.wz.data(), m.radius_m.data(), m.inv_spin.data(), m.rows.data()};
}

PlatenView view(PlatenArrays& a, std::size_t platen) {
  const std::size_t at = platen * a.particles;
  return {view(a.constants), a.spring_x.data() + at, a.spring_y.data() + at, a.spring_z.data() + at,
          a.fx.data() + at,  a.fy.data() + at,       a.fz.data() + at,       a.tx.data() + at,
          a.ty.data() + at,  a.tz.data() + at,       a.normal_N.data() + at, a.near.data() + at};
}

void bonds_scalar(const BondView& b, const MotionView& m, const BondStep& s, std::size_t begin,
                  std::size_t end) {
  for (std::size_t k = begin; k < end; ++k) {
    bond_lane(b, sphere_of(m, static_cast<std::size_t>(b.i[k])),
              sphere_of(m, static_cast<std::size_t>(b.j[k])), s, k);
  }
}

void contacts_scalar(const ContactView& c, const MotionView& m, const ContactStep& s,
                     std::size_t begin, std::size_t end) {
  for (std::size_t k = begin; k < end; ++k) {
    contact_pair_lane(c, sphere_of(m, static_cast<std::size_t>(c.i[k])),
                      sphere_of(m, static_cast<std::size_t>(c.j[k])), s, k);
  }
}

void platens_scalar(const PlatenView& c, const MotionView& m, const PlatenStep& s,
                    std::size_t begin, std::size_t end) {
  for (std::size_t k = begin; k < end; ++k) platen_lane(c, m, s, k);
}

}  // namespace planter::dem::lanes
