#include "dem/dem_world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace planter::dem {
namespace {

double max_radius(const std::vector<Particle>& ps) {
  double r = 0.0;
  for (const auto& p : ps) r = std::max(r, p.radius_m);
  return r;
}

// Cundall's local damping on one vector: each component loses `fraction` of its size,
// in the direction that opposes the matching velocity component.
void damp(Vec3& load, const Vec3& velocity, double fraction) {
  for (int k = 0; k < 3; ++k) {
    const double s = velocity[k] > 0.0 ? 1.0 : (velocity[k] < 0.0 ? -1.0 : 0.0);
    load[k] -= fraction * std::abs(load[k]) * s;
  }
}

}  // namespace

int DemWorld::add_particle(const Particle& p) {
  particles_.push_back(p);
  neighbours_valid_ = false;
  return static_cast<int>(particles_.size() - 1);
}

void DemWorld::add_bond(int i, int j) {
  Bond b;
  b.i = std::min(i, j);
  b.j = std::max(i, j);
  const Particle& pi = particles_[static_cast<std::size_t>(b.i)];
  const Particle& pj = particles_[static_cast<std::size_t>(b.j)];
  b.rest_overlap_m = std::max(0.0, pi.radius_m + pj.radius_m - (pj.x - pi.x).norm());
  bonds_.push_back(b);
  neighbours_valid_ = false;
}

int DemWorld::bond_neighbours(double gap_m) {
  cells_.build(particles_, 2.0 * max_radius(particles_) + gap_m);
  cells_.pairs(particles_, pairs_scratch_);
  int added = 0;
  for (const auto& [i, j] : pairs_scratch_) {
    const Particle& a = particles_[static_cast<std::size_t>(i)];
    const Particle& b = particles_[static_cast<std::size_t>(j)];
    if ((b.x - a.x).norm() <= a.radius_m + b.radius_m + gap_m) {
      add_bond(i, j);
      ++added;
    }
  }
  return added;
}

int DemWorld::add_platen(const Platen& p) {
  platens_.push_back(p);
  platens_.back().normal.normalize();
  neighbours_valid_ = false;
  return static_cast<int>(platens_.size() - 1);
}

bool DemWorld::neighbours_stale() const {
  if (!neighbours_valid_) return true;
  const double limit2 = 0.25 * skin_m_ * skin_m_;
  for (std::size_t k = 0; k < particles_.size(); ++k) {
    if ((particles_[k].x - x_at_rebuild_[k]).squaredNorm() > limit2) return true;
  }
  return false;
}

void DemWorld::rebuild_neighbours() {
  const double r_max = max_radius(particles_);
  skin_m_ = 0.2 * r_max;
  cells_.build(particles_, 2.0 * r_max + skin_m_);
  cells_.pairs(particles_, pairs_scratch_);
  std::sort(pairs_scratch_.begin(), pairs_scratch_.end());
  // Bonds ordered by pair, to mark bonded candidates by a merge.
  std::vector<std::pair<std::pair<int, int>, int>> bond_keys;
  bond_keys.reserve(bonds_.size());
  for (std::size_t b = 0; b < bonds_.size(); ++b) {
    bond_keys.push_back({{bonds_.i[b], bonds_.j[b]}, static_cast<int>(b)});
  }
  std::sort(bond_keys.begin(), bond_keys.end());
  std::swap(previous_, candidates_);  // ordered by (i, j) as built last time
  candidates_.clear();
  std::size_t prev = 0;
  std::size_t bk = 0;
  for (const auto& key : pairs_scratch_) {
    int bond = -1;
    while (bk < bond_keys.size() && bond_keys[bk].first < key) ++bk;
    if (bk < bond_keys.size() && bond_keys[bk].first == key) bond = bond_keys[bk].second;
    while (prev < previous_.size() && std::make_pair(previous_.i[prev], previous_.j[prev]) < key) {
      ++prev;
    }
    const bool kept = prev < previous_.size() && previous_.i[prev] == key.first &&
                      previous_.j[prev] == key.second;
    const Particle& a = particles_[static_cast<std::size_t>(key.first)];
    const Particle& b = particles_[static_cast<std::size_t>(key.second)];
    // The Hertz contact acts in parallel with a bond (Potyondy and Cundall 2004: the parallel
    // bond is "in parallel with" the contact), from the pair's as-built overlap. Switching it
    // on only when the bond broke started it at the full overlap the soft bond had allowed:
    // energy from nothing, which shattered the seedling.
    const double rest = bond >= 0 ? bonds_.rest_overlap_m[static_cast<std::size_t>(bond)] : 0.0;
    candidates_.push_back(key.first, key.second, bond, rest,
                          pair_properties(material_, a.radius_m, b.radius_m, a.mass_kg, b.mass_kg),
                          kept ? previous_.spring(prev) : Vec3::Zero());
  }
  x_at_rebuild_.resize(particles_.size());
  for (std::size_t k = 0; k < particles_.size(); ++k) x_at_rebuild_[k] = particles_[k].x;
  bonds_of_.build(particles_.size(), bonds_.i, bonds_.j);
  contacts_of_.build(particles_.size(), candidates_.i, candidates_.j);
  // Every platen is the same steel: one pair per particle, not one per contact and step.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<PairProperties> against_platen;
  against_platen.reserve(particles_.size());
  for (const auto& p : particles_) {
    against_platen.push_back(pair_properties(material_, platen_material_,
                                             platen_material_.restitution, p.radius_m, kInf,
                                             p.mass_kg, kInf));
  }
  platen_contacts_.resize(platens_.size(), against_platen);
  neighbours_valid_ = true;
  ++rebuilds_;
}

void DemWorld::add_platen_loads(std::size_t i, Particle& p) const {
  const PlatenArrays& c = platen_contacts_;
  for (std::size_t k = 0; k < platens_.size(); ++k) {
    const std::size_t at = k * c.particles + i;
    if (c.near[at] == 0.0) continue;  // no contact: nothing added (not even a zero)
    p.f += Vec3(c.fx[at], c.fy[at], c.fz[at]);
    p.tau += Vec3(c.tx[at], c.ty[at], c.tz[at]);
  }
}

void DemWorld::integrate(Particle& p, double dt) const {
  if (p.fixed) return;
  if (local_damping_ > 0.0) {
    damp(p.f, p.v, local_damping_);
    damp(p.tau, p.w, local_damping_);
  }
  p.v += p.f / p.mass_kg * dt;
  p.x += p.v * dt;
  if (p.inertia_kgm2 > 0.0) p.w += p.tau / p.inertia_kgm2 * dt;
}

void DemWorld::particle_step(std::size_t i, bool sum_pairs, double dt) {
  Particle& p = particles_[i];
  // Bonds, then contacts, then platens, each in pair order: the order of the sums is the
  // result's, and it is the same for every particle whichever thread sums it.
  if (sum_pairs) {
    p.f.setZero();
    p.tau.setZero();
    add_pair_loads(bonds_.loads, bonds_of_, i, p);
    add_pair_loads(candidates_.loads, contacts_of_, i, p);
  }
  add_platen_loads(i, p);
  integrate(p, dt);
}

void DemWorld::step(double dt) {
  if (neighbours_stale()) rebuild_neighbours();
  motion_.assign(particles_, reads_motion_rows(vector_path_));
  const BondStep bond_constants = bond_step(bond_params_, dt);
  const auto parts = static_cast<std::size_t>(threads_->threads());
  // Part k of n things: an equal share.
  const auto share = [parts](std::size_t n, int k) {
    const auto kk = static_cast<std::size_t>(k);
    return std::pair<std::size_t, std::size_t>{n * kk / parts, n * (kk + 1) / parts};
  };
  // First every pair's loads (each pair writes only its own), then every particle's sums and
  // motion (each particle only its own): two parts per thread, the second after all of the
  // first.
  auto pairs = [&](int k) {
    const auto [b0, b1] = share(bonds_.size(), k);
    update_bonds(vector_path_, bonds_, motion_, bond_constants, b0, b1);
    const auto [c0, c1] = share(candidates_.size(), k);
    update_contacts(vector_path_, candidates_, motion_, material_.friction,
                    material_.rolling_friction, dt, c0, c1);
    const auto [p0, p1] = share(particles_.size(), k);
    for (std::size_t w = 0; w < platens_.size(); ++w) {
      update_platen_contacts(vector_path_, platen_contacts_, w, platens_[w].point,
                             platens_[w].normal, platens_[w].velocity, motion_,
                             platen_material_.friction, platen_material_.rolling_friction, dt, p0,
                             p1);
    }
  };
  threads_->run(pairs);
  // On one thread the pairs' loads are added in one pass over the pairs (the arrays read in
  // order: 5 % faster here); on several, each particle gathers its own. The same sums.
  const bool gather = parts > 1;
  if (!gather) {
    for (auto& p : particles_) {
      p.f.setZero();
      p.tau.setZero();
    }
    add_all_pair_loads(bonds_.loads, bonds_.i, bonds_.j, particles_);
    add_all_pair_loads(candidates_.loads, candidates_.i, candidates_.j, particles_);
  }
  auto particles = [&](int k) {
    const auto [p0, p1] = share(particles_.size(), k);
    for (std::size_t i = p0; i < p1; ++i) particle_step(i, gather, dt);
  };
  threads_->run(particles);
  // Each platen's force: its particles' normal forces summed in particle order.
  const std::size_t n = particles_.size();
  for (std::size_t k = 0; k < platens_.size(); ++k) {
    Platen& w = platens_[k];
    w.force_N = 0.0;
    for (std::size_t i = 0; i < n; ++i) w.force_N += platen_contacts_.normal_N[k * n + i];
    w.point += w.velocity * dt;
  }
  ++steps_;
}

int DemWorld::broken_bonds() const {
  return static_cast<int>(std::count_if(bonds_.broken.begin(), bonds_.broken.end(),
                                        [](double broken) { return broken != 0.0; }));
}

std::vector<Bond> DemWorld::bonds() const {
  std::vector<Bond> out;
  out.reserve(bonds_.size());
  for (std::size_t k = 0; k < bonds_.size(); ++k) out.push_back(bonds_.bond(k));
  return out;
}

double DemWorld::kinetic_energy() const {
  double e = 0.0;
  for (const auto& p : particles_) {
    e += 0.5 * p.mass_kg * p.v.squaredNorm() + 0.5 * p.inertia_kgm2 * p.w.squaredNorm();
  }
  return e;
}

double DemWorld::contact_energy() const {
  double e = 0.0;
  for (std::size_t k = 0; k < candidates_.size(); ++k) {
    const Particle& a = particles_[static_cast<std::size_t>(candidates_.i[k])];
    const Particle& b = particles_[static_cast<std::size_t>(candidates_.j[k])];
    e += hertz_energy(candidates_.properties(k),
                      a.radius_m + b.radius_m - candidates_.rest_overlap_m[k] - (b.x - a.x).norm());
  }
  return e;
}

double DemWorld::bond_energy() const {
  double e = 0.0;
  for (std::size_t k = 0; k < bonds_.size(); ++k) {
    e += dem::bond_energy(bonds_.bond(k), bond_params_);
  }
  return e;
}

}  // namespace planter::dem
