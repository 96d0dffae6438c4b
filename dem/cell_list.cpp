#include "dem/cell_list.h"

#include <algorithm>
#include <cmath>

namespace planter::dem {

void CellList::build(const std::vector<Particle>& ps, double range_m) {
  range_m_ = range_m;
  cell_m_ = std::max(range_m, 1e-9);
  Vec3 lo = Vec3::Constant(1e300);
  Vec3 hi = Vec3::Constant(-1e300);
  for (const auto& p : ps) {
    lo = lo.cwiseMin(p.x);
    hi = hi.cwiseMax(p.x);
  }
  if (ps.empty()) lo = hi = Vec3::Zero();
  origin_ = lo;
  // A particle that flew far away must not make the grid huge: widen the cells instead
  // (correct, only slower), keeping at most about 8 cells per particle.
  const Vec3 extent = hi - lo;
  const double budget = 8.0 * static_cast<double>(ps.size()) + 64.0;
  while ((extent.x() / cell_m_ + 1) * (extent.y() / cell_m_ + 1) * (extent.z() / cell_m_ + 1) >
         budget)
    cell_m_ *= 2.0;
  auto count = [&](double span) {
    return std::max(1, static_cast<int>(std::floor(span / cell_m_)) + 1);
  };
  nx_ = count(hi.x() - lo.x());
  ny_ = count(hi.y() - lo.y());
  nz_ = count(hi.z() - lo.z());
  const std::size_t cells = static_cast<std::size_t>(nx_) * ny_ * nz_;
  cell_start_.assign(cells + 1, 0);
  cell_of_.resize(ps.size());
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const Vec3 r = (ps[k].x - origin_) / cell_m_;
    const int cx = std::clamp(static_cast<int>(r.x()), 0, nx_ - 1);
    const int cy = std::clamp(static_cast<int>(r.y()), 0, ny_ - 1);
    const int cz = std::clamp(static_cast<int>(r.z()), 0, nz_ - 1);
    cell_of_[k] = (cz * ny_ + cy) * nx_ + cx;
    ++cell_start_[static_cast<std::size_t>(cell_of_[k]) + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  order_.resize(ps.size());
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t k = 0; k < ps.size(); ++k)
    order_[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_of_[k])]++)] =
        static_cast<int>(k);
}

void CellList::pairs(const std::vector<Particle>& ps, std::vector<std::pair<int, int>>& out) const {
  out.clear();
  const double r2 = range_m_ * range_m_;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const int c = cell_of_[i];
    const int cx = c % nx_;
    const int cy = (c / nx_) % ny_;
    const int cz = c / (nx_ * ny_);
    for (int dz = -1; dz <= 1; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = cx + dx, y = cy + dy, z = cz + dz;
          if (x < 0 || y < 0 || z < 0 || x >= nx_ || y >= ny_ || z >= nz_) continue;
          const auto cell = static_cast<std::size_t>((z * ny_ + y) * nx_ + x);
          for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
            const int j = order_[static_cast<std::size_t>(k)];
            if (j <= static_cast<int>(i)) continue;
            if ((ps[static_cast<std::size_t>(j)].x - ps[i].x).squaredNorm() <= r2)
              out.emplace_back(static_cast<int>(i), j);
          }
        }
      }
    }
  }
  std::sort(out.begin(), out.end());
}

}  // namespace planter::dem
