#include "dem/pair_loads.h"

namespace planter::dem {

void PairLoads::resize(std::size_t pairs) {
  for (auto* a : {&force_on_i_x, &force_on_i_y, &force_on_i_z, &torque_on_i_x, &torque_on_i_y,
                  &torque_on_i_z, &torque_on_j_x, &torque_on_j_y, &torque_on_j_z, &carried}) {
    a->resize(pairs, 0.0);
  }
}

void add_pair_loads(const PairLoads& l, const Incidence& pairs_of, std::size_t p,
                    Particle& particle) {
  const auto end = static_cast<std::size_t>(pairs_of.start[p + 1]);
  for (auto e = static_cast<std::size_t>(pairs_of.start[p]); e < end; ++e) {
    const auto k = static_cast<std::size_t>(pairs_of.pair[e]);
    if (l.carried[k] == 0.0) continue;
    const Vec3 f(l.force_on_i_x[k], l.force_on_i_y[k], l.force_on_i_z[k]);
    if (pairs_of.is_j[e] != 0) {
      particle.f -= f;
      particle.tau += Vec3(l.torque_on_j_x[k], l.torque_on_j_y[k], l.torque_on_j_z[k]);
    } else {
      particle.f += f;
      particle.tau += Vec3(l.torque_on_i_x[k], l.torque_on_i_y[k], l.torque_on_i_z[k]);
    }
  }
}

void add_all_pair_loads(const PairLoads& l, const std::vector<int>& i, const std::vector<int>& j,
                        std::vector<Particle>& particles) {
  // add_pair_loads' two sides with one test and one read of the force (a tenth of a step).
  for (std::size_t k = 0; k < i.size(); ++k) {
    if (l.carried[k] == 0.0) continue;
    Particle& a = particles[static_cast<std::size_t>(i[k])];
    Particle& b = particles[static_cast<std::size_t>(j[k])];
    const Vec3 f(l.force_on_i_x[k], l.force_on_i_y[k], l.force_on_i_z[k]);
    a.f += f;
    b.f -= f;
    a.tau += Vec3(l.torque_on_i_x[k], l.torque_on_i_y[k], l.torque_on_i_z[k]);
    b.tau += Vec3(l.torque_on_j_x[k], l.torque_on_j_y[k], l.torque_on_j_z[k]);
  }
}

}  // namespace planter::dem
