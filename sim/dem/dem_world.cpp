#include "sim/dem/dem_world.h"

#include <algorithm>
#include <limits>

namespace planter::dem {

int DemWorld::add_particle(const Particle& p) {
  particles_.push_back(p);
  return static_cast<int>(particles_.size() - 1);
}

void DemWorld::add_bond(int i, int j) {
  Bond b;
  b.i = std::min(i, j);
  b.j = std::max(i, j);
  bonds_.push_back(b);
}

int DemWorld::bond_neighbours(double gap_m) {
  double r_max = 0.0;
  for (const auto& p : particles_) r_max = std::max(r_max, p.radius_m);
  cells_.build(particles_, 2.0 * r_max + gap_m);
  cells_.pairs(particles_, candidates_);
  int added = 0;
  for (const auto& [i, j] : candidates_) {
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
  return static_cast<int>(platens_.size() - 1);
}

void DemWorld::contacts(double dt) {
  double r_max = 0.0;
  for (const auto& p : particles_) r_max = std::max(r_max, p.radius_m);
  cells_.build(particles_, 2.0 * r_max);
  cells_.pairs(particles_, candidates_);
  std::map<std::pair<int, int>, Vec3> next;
  for (const auto& key : candidates_) {
    Particle& a = particles_[static_cast<std::size_t>(key.first)];
    Particle& b = particles_[static_cast<std::size_t>(key.second)];
    if ((b.x - a.x).norm() >= a.radius_m + b.radius_m) continue;
    Vec3 spring = Vec3::Zero();
    if (auto it = springs_.find(key); it != springs_.end()) spring = it->second;
    const PairProperties pp =
        pair_properties(material_, a.radius_m, b.radius_m, a.mass_kg, b.mass_kg);
    const ContactResult r = hertz_mindlin(material_, pp, a, b, dt, spring);
    a.f += r.force_on_i;
    b.f -= r.force_on_i;
    a.tau += r.torque_on_i;
    b.tau += r.torque_on_j;
    next.emplace(key, spring);
  }
  springs_.swap(next);
  // Platens: a wall is a sphere of infinite radius and mass at the particle's foot point.
  std::map<std::pair<int, int>, Vec3> next_platen;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < platens_.size(); ++k) {
    Platen& w = platens_[k];
    w.force_N = 0.0;
    for (std::size_t i = 0; i < particles_.size(); ++i) {
      Particle& p = particles_[i];
      const double h = (p.x - w.point).dot(w.normal);
      if (h >= p.radius_m) continue;
      Particle wall;
      wall.radius_m = 1.0;  // geometry only: the pair below treats the wall as flat (R* = r)
      wall.x = p.x - (h + wall.radius_m) * w.normal;
      wall.v = w.velocity;
      wall.mass_kg = kInf;
      const std::pair<int, int> key{static_cast<int>(k), static_cast<int>(i)};
      Vec3 spring = Vec3::Zero();
      if (auto it = platen_springs_.find(key); it != platen_springs_.end()) spring = it->second;
      const PairProperties pp = pair_properties(material_, p.radius_m, kInf, p.mass_kg, kInf);
      const ContactResult r = hertz_mindlin(material_, pp, p, wall, dt, spring);
      p.f += r.force_on_i;
      p.tau += r.torque_on_i;
      w.force_N += r.normal_force_N;
      next_platen.emplace(key, spring);
    }
  }
  platen_springs_.swap(next_platen);
}

void DemWorld::step(double dt) {
  for (auto& p : particles_) {
    p.f.setZero();
    p.tau.setZero();
  }
  for (auto& b : bonds_) {
    update_bond(b, bond_params_, particles_[static_cast<std::size_t>(b.i)],
                particles_[static_cast<std::size_t>(b.j)], dt);
  }
  contacts(dt);
  for (auto& p : particles_) {
    if (p.fixed) continue;
    p.v += p.f / p.mass_kg * dt;
    p.x += p.v * dt;
    if (p.inertia_kgm2 > 0.0) p.w += p.tau / p.inertia_kgm2 * dt;
  }
  for (auto& w : platens_) w.point += w.velocity * dt;
  ++steps_;
}

int DemWorld::broken_bonds() const {
  return static_cast<int>(
      std::count_if(bonds_.begin(), bonds_.end(), [](const Bond& b) { return b.broken; }));
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
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    for (std::size_t j = i + 1; j < particles_.size(); ++j) {
      const Particle& a = particles_[i];
      const Particle& b = particles_[j];
      const double overlap = a.radius_m + b.radius_m - (b.x - a.x).norm();
      if (overlap <= 0.0) continue;
      e += hertz_energy(pair_properties(material_, a.radius_m, b.radius_m, a.mass_kg, b.mass_kg),
                        overlap);
    }
  }
  return e;
}

double DemWorld::bond_energy() const {
  double e = 0.0;
  for (const auto& b : bonds_) e += dem::bond_energy(b, bond_params_);
  return e;
}

}  // namespace planter::dem
