#include "sim/plant/seedling_release.h"

#include <algorithm>
#include <cmath>

namespace planter::sim {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kRadPerDeg = kPi / 180.0;
constexpr double kG = 9.81;
// Steps per radian of disc travel: the held stage spans up to about 60 deg, the release about 40.
constexpr double kStepsPerRad = 240.0;
}  // namespace

ReleaseOutcome release_seedling(const PlantConfig& config, const ReleaseInput& in) {
  const MechanismConfig& mc = config.mechanism;
  const soil::RootAnchorage soil(config.soil.ground);
  const double r_rim = config.disc_radius_m;
  const double protrusion = mc.root_protrusion_mm * 1e-3;
  const double r_root = r_rim + protrusion;
  const double reach = mc.root_reach_mm * 1e-3;
  const double floor = std::max(0.0, in.depth_mm) * 1e-3;
  const double length = in.length_mm * 1e-3;
  const double diameter = in.diameter_mm * 1e-3;
  const double omega = std::max(1e-3, in.omega_radps);
  const double v = in.v_mps;
  const double theta_r = mc.release_after_lowest_deg * kRadPerDeg;
  const double dtheta = 1.0 / kStepsPerRad;
  const double dt = dtheta / omega;
  ReleaseOutcome out;

  // Depth of the root end below the surface at disc angle theta (0 at the lowest point), on the
  // floor at most.
  auto burial = [&](double theta) {
    return std::clamp(reach - r_root * (1.0 - std::cos(theta)), 0.0, floor);
  };
  // The opener leaves the furrow open; the returning soil has refilled a share of it where the
  // seedling goes in. The root holds in that soil only.
  const double backflow_level = mc.backflow_fill * floor;  // above the floor
  auto embedded = [&](double theta) {
    return std::max(0.0, backflow_level - (floor - burial(theta)));
  };

  // 1. Held: from where the root end reaches the surface to the release. The lips are a
  // distributed spring over the held length w: the clamp law's local stiffness dF/dx = n F / x
  // ([plant] clamp_k_N, clamp_n) spread over w resists turning with k w^2 / 12.
  const double entry = -std::acos(std::clamp(1.0 - reach / r_root, -1.0, 1.0));
  const double held_length = mc.contact_area_mm2 * 1e-6 / std::max(1e-4, diameter);
  const double clamp_N = std::max(0.0, in.clamp_force_N);
  const double hold_Nm = mc.lip_friction * clamp_N * held_length / 4.0;
  const DriveModelConfig& dr = config.drive;
  const double lip_compression_mm = std::pow(clamp_N / dr.clamp_k_N, 1.0 / dr.clamp_n);
  const double lip_N_per_m = 1e3 * dr.clamp_n * clamp_N / std::max(0.1, lip_compression_mm);
  const double lip_Nm_per_rad = std::max(1e-6, lip_N_per_m * held_length * held_length / 12.0);
  double slipped = 0.0;  // turned by slipping in the clamp, + top forward
  double elastic = 0.0;  // the lips' elastic give, at the release
  for (double theta = entry; theta < theta_r; theta += dtheta) {
    const double b = embedded(theta);
    const double u_root = v - r_root * omega * std::cos(theta);  // root end's ground speed
    // The soil pushes the root against its travel: travelling backwards (sigma > 1 near the
    // lowest point) the root is pushed forwards, ahead of the clamp, and the top turns back.
    const double moment = soil.plowing_force_N(diameter, b) * std::max(0.0, protrusion - b / 3.0) *
                          (u_root < 0.0 ? -1.0 : 1.0);
    elastic = std::clamp(moment, -hold_Nm, hold_Nm) / lip_Nm_per_rad;
    // Past the grip the root stays where the soil holds it while the clamp moves on.
    if (std::abs(moment) > hold_Nm) slipped += u_root * dt / protrusion;
  }
  const double turn = slipped + elastic;
  out.clamp_turn_deg = turn / kRadPerDeg;

  // 2. Released: the rod about its root end, (x, y) with y up from the soil surface.
  const double b = embedded(theta_r);
  out.burial_mm = burial(theta_r) * 1e3;
  double phi = theta_r + turn;  // + top forward
  const double hub_height = r_root - reach;
  const double root_x = -r_root * std::sin(theta_r);  // hub at x = 0 at release
  const double root_y = -burial(theta_r);
  const double grip_N = mc.lip_friction * mc.residual_grip_share * std::max(0.0, in.clamp_force_N);
  const double phi_release = phi;
  for (double t = 0.0; t < 2.0 * kPi / omega; t += dt) {
    const double hub_x = v * t;
    const double ux = std::sin(phi), uy = std::cos(phi);
    // Where the rod enters the disc's circle: |root + s u - hub| = R.
    const double qx = root_x - hub_x, qy = root_y - hub_height;
    const double qu = qx * ux + qy * uy;
    const double disc = qu * qu - (qx * qx + qy * qy - r_rim * r_rim);
    if (disc < 0.0) break;
    const double s = -qu - std::sqrt(disc);
    if (s >= length) break;  // its top has left the disc
    const double s_c = std::max(s, 1e-3);
    // The disc's surface at that point (bottom moving backwards), across the rod.
    const double px = qx + s_c * ux, py = qy + s_c * uy;
    const double vx = v + omega * py, vy = -omega * px;
    const double across = vx * uy - vy * ux;  // along (cos phi, -sin phi): + top forward
    const double lips_height = root_y + s_c * uy + (floor - backflow_level);
    if (grip_N > soil.holding_force_N(diameter, b, lips_height)) phi += across * dt / s_c;
  }
  out.lip_drag_deg = (phi - phi_release) / kRadPerDeg;
  phi += in.scatter_deg * kRadPerDeg;

  // 3. Standing: the weight's moment about the root end against the soil's.
  const double mass = config.seedlings.density_kg_per_m3 * kPi / 4.0 * diameter * diameter * length;
  const double weight_Nm = mass * kG * 0.5 * length * std::abs(std::sin(phi));
  if (weight_Nm > soil.holding_moment_Nm(diameter, b)) {
    out.lodged = true;
    phi = std::copysign(90.0 * kRadPerDeg, phi);
  }
  out.tilt_deg = std::clamp(phi / kRadPerDeg, -90.0, 90.0);
  return out;
}

}  // namespace planter::sim
