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
  // add_pair_loads' two sides with one test and one read of the force. The arrays' addresses
  // are taken once: Eigen's stores into the particles may alias anything, and the compiler
  // reloaded every address for every pair.
  const double* const carried = l.carried.data();
  const double* const fx = l.force_on_i_x.data();
  const double* const fy = l.force_on_i_y.data();
  const double* const fz = l.force_on_i_z.data();
  const double* const tix = l.torque_on_i_x.data();
  const double* const tiy = l.torque_on_i_y.data();
  const double* const tiz = l.torque_on_i_z.data();
  const double* const tjx = l.torque_on_j_x.data();
  const double* const tjy = l.torque_on_j_y.data();
  const double* const tjz = l.torque_on_j_z.data();
  const int* const pi = i.data();
  const int* const pj = j.data();
  Particle* const ps = particles.data();
  // The pairs come grouped by their i: that particle's sums are held in registers while its
  // pairs last, not stored and loaded back for each. The same additions in the same order.
  int held = -1;
  Vec3 f_held = Vec3::Zero();
  Vec3 tau_held = Vec3::Zero();
  const auto let_go = [&] {
    if (held < 0) return;
    ps[held].f = f_held;
    ps[held].tau = tau_held;
  };
  const std::size_t n = i.size();
  for (std::size_t k = 0; k < n; ++k) {
    if (carried[k] == 0.0) continue;
    const int a = pi[k];
    const int b = pj[k];
    if (a != held) {
      let_go();
      held = a;
      f_held = ps[a].f;
      tau_held = ps[a].tau;
    }
    const Vec3 f(fx[k], fy[k], fz[k]);
    const Vec3 tj(tjx[k], tjy[k], tjz[k]);
    f_held += f;
    tau_held += Vec3(tix[k], tiy[k], tiz[k]);
    if (b == held) {
      f_held -= f;
      tau_held += tj;
    } else {
      Particle& other = ps[b];
      other.f -= f;
      other.tau += tj;
    }
  }
  let_go();
}

}  // namespace planter::dem
