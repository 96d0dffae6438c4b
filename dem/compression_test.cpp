#include "dem/compression_test.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace planter::dem {

namespace {

// Smoothed over a few samples, so that one noisy sample is not a peak.
std::vector<double> smoothed_force(const std::vector<CurvePoint>& curve, std::size_t half) {
  const std::size_t n = curve.size();
  std::vector<double> smooth(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t lo = k >= half ? k - half : 0;
    const std::size_t hi = std::min(n - 1, k + half);
    for (std::size_t m = lo; m <= hi; ++m) smooth[k] += curve[m].force_N;
    smooth[k] /= static_cast<double>(hi - lo + 1);
  }
  return smooth;
}

std::size_t smoothing_half_width(std::size_t n) { return std::max<std::size_t>(1, n / 120); }

// The raw curve's largest value within `half` samples of a smoothed peak at `at`: the figure
// reported is one the curve holds, not the smoothing's.
void raw_peak_near(const std::vector<CurvePoint>& curve, std::size_t at, std::size_t half,
                   double& force_N, double& displacement_m) {
  const std::size_t n = curve.size();
  for (std::size_t m = at >= half ? at - half : 0; m <= std::min(n - 1, at + half); ++m) {
    if (curve[m].force_N > force_N) {
      force_N = curve[m].force_N;
      displacement_m = curve[m].displacement_m;
    }
  }
}

// The collapse is the peak the force falls furthest from before it climbs above that peak
// again (densification): a drop of a few bonds before it can be the first peak, and the chart
// shows both.
void set_collapse(CompressionResult& r, const std::vector<double>& smooth, std::size_t half) {
  const std::size_t n = smooth.size();
  r.collapse_drop_N = 0.0;
  r.collapse_force_N = 0.0;
  r.collapse_displacement_m = 0.0;
  std::size_t at = n;
  for (std::size_t i = 0; i < n; ++i) {
    double low = smooth[i];
    for (std::size_t j = i + 1; j < n && smooth[j] <= smooth[i]; ++j)
      low = std::min(low, smooth[j]);
    if (smooth[i] - low > r.collapse_drop_N) {
      r.collapse_drop_N = smooth[i] - low;
      at = i;
    }
  }
  if (at < n) raw_peak_near(r.curve, at, half, r.collapse_force_N, r.collapse_displacement_m);
}

}  // namespace

void find_collapse(CompressionResult& r) {
  const std::size_t half = smoothing_half_width(r.curve.size());
  set_collapse(r, smoothed_force(r.curve, half), half);
}

std::string collapse_text(const CompressionResult& r) {
  if (r.collapse_drop_N <= 0.0) return "none: the force never falls within the stroke";
  char text[64];
  std::snprintf(text, sizeof text, "%.1f N at %.2f mm", r.collapse_force_N,
                r.collapse_displacement_m * 1e3);
  return text;
}

void find_first_peak(CompressionResult& r, double drop_fraction) {
  // Smoothed over a few samples, so that one noisy sample is not a peak; the seating of
  // the first few tenths of a millimetre is not either.
  constexpr double kSeating_m = 0.3e-3;
  const std::size_t n = r.curve.size();
  const std::size_t half = smoothing_half_width(n);
  const std::vector<double> smooth = smoothed_force(r.curve, half);
  r.first_peak_found = false;
  double best = -1.0;
  std::size_t best_k = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (r.curve[k].displacement_m < kSeating_m) continue;
    if (smooth[k] > best) {
      best = smooth[k];
      best_k = k;
    } else if (best > 0.0 && smooth[k] < (1.0 - drop_fraction) * best) {
      r.first_peak_found = true;
      break;
    }
  }
  set_collapse(r, smooth, half);
  r.peak_force_N = 0.0;
  r.peak_displacement_m = 0.0;
  if (best >= 0.0) raw_peak_near(r.curve, best_k, half, r.peak_force_N, r.peak_displacement_m);
}

CompressionWorld make_compression_world(const CompressionSetup& s) {
  CompressionWorld c{DemWorld(s.seedling_material, s.bonds, s.platen_material), {}, 0, 0.0};
  c.world.set_local_damping(s.local_damping);
  c.seedling = build_seedling(c.world, s.seedling);
  c.platen_speed_mps = s.platen_speed_mps * s.speedup;
  Platen lower;
  lower.point = Vec3(0.0, c.seedling.min_y_m, 0.0);
  lower.normal = Vec3::UnitY();
  c.world.add_platen(lower);
  Platen upper;
  upper.point = Vec3(0.0, c.seedling.max_y_m, 0.0);
  upper.normal = -Vec3::UnitY();
  upper.velocity = Vec3(0.0, -c.platen_speed_mps, 0.0);
  c.upper_platen = c.world.add_platen(upper);
  return c;
}

long compression_steps(const CompressionSetup& s) {
  return std::lround(s.stroke_m / (s.platen_speed_mps * s.speedup) / s.time_step_s);
}

CompressionResult run_compression(const CompressionSetup& s, int threads,
                                  const std::function<void(const CurvePoint&)>& on_sample) {
  CompressionWorld c = make_compression_world(s);
  DemWorld& world = c.world;
  world.set_threads(threads);
  const SeedlingBuild& built = c.seedling;
  const double speed = c.platen_speed_mps;
  const int top = c.upper_platen;

  CompressionResult r;
  r.particles = built.particles;
  r.bonds = built.bonds;
  const long total_steps = compression_steps(s);
  const long per_sample = std::max(1L, total_steps / std::max(1, s.samples));
  double force_sum = 0.0;
  double work_J = 0.0;
  long in_sample = 0;
  for (long k = 1; k <= total_steps; ++k) {
    world.step(s.time_step_s);
    const double f = world.platens()[static_cast<std::size_t>(top)].force_N;
    force_sum += f;
    work_J += f * speed * s.time_step_s;
    if (++in_sample == per_sample || k == total_steps) {
      CurvePoint p;
      p.displacement_m = speed * s.time_step_s * static_cast<double>(k);
      p.force_N = force_sum / static_cast<double>(in_sample);
      p.broken_bonds = world.broken_bonds();
      r.curve.push_back(p);
      if (on_sample) on_sample(p);
      if (p.displacement_m > 0.1 * s.stroke_m && work_J > 0.0) {
        r.max_kinetic_to_work = std::max(r.max_kinetic_to_work, world.kinetic_energy() / work_J);
      }
      force_sum = 0.0;
      in_sample = 0;
    }
  }
  r.steps = world.steps();
  r.broken_bonds = world.broken_bonds();
  find_first_peak(r, s.peak_drop_fraction);
  return r;
}

}  // namespace planter::dem
