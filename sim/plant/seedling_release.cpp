#include "sim/plant/seedling_release.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "config/clamp_ceiling.h"

namespace planter::sim {
namespace {
constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr double kG = 9.81;
// Steps per radian of disc travel: the held stage spans up to about 60 deg, the release about 40.
constexpr double kStepsPerRad = 240.0;
// The standing stage's time step (s): the fall of a 0.2 m rod about its end takes about 0.3 s.
constexpr double kFallStep_s = 0.002;
// With the machine stopped the covering wheel does not come: the stage ends after this long.
constexpr double kLongestWait_s = 60.0;

double seedling_mass_kg(const PlantConfig& config, double length_m, double diameter_m) {
  return config.seedlings.density_kg_per_m3 * std::numbers::pi / 4.0 * diameter_m * diameter_m *
         length_m;
}
}  // namespace

double held_length_m(const MechanismConfig& mc, double diameter_mm) {
  return config::held_length_mm(mc.contact_area_mm2, mc.protrusion_band_mm, diameter_mm) * 1e-3;
}

double lip_turning_stiffness_Nm_per_rad(const MechanismConfig& mc, double diameter_mm) {
  const double w = held_length_m(mc, diameter_mm), d = std::max(0.1, diameter_mm) * 1e-3;
  const double area = w * d;  // per face
  return 2.0 * mc.lip_shear_modulus_MPa * 1e6 * area * (w * w + d * d) /
         (12.0 * std::max(1e-6, mc.lip_shear_layer_mm * 1e-3));
}

double carry_grip_needed_N(const PlantConfig& config, double length_mm, double diameter_mm,
                           double omega_radps) {
  const MechanismConfig& mc = config.mechanism;
  const double length = length_mm * 1e-3;
  const double mass = seedling_mass_kg(config, length, diameter_mm * 1e-3);
  // Its centre of mass sits about half its length inside the rim (the root end protrudes).
  const double r_cm =
      std::max(0.0, config.disc_radius_m + mc.root_protrusion_mm * 1e-3 - 0.5 * length);
  const double accel = kG + omega_radps * omega_radps * r_cm +
                       mc.handoff_speed_mismatch_mps / std::max(1e-3, mc.nip_time_s);
  return mass * accel / std::max(1e-9, 2.0 * mc.lip_friction);
}

ReleaseOutcome release_seedling(const PlantConfig& config, const ReleaseInput& in) {
  const MechanismConfig& mc = config.mechanism;
  const soil::RootAnchorage backflow(config.soil.backflow);
  const soil::RootAnchorage firmed(config.soil.firmed);
  const double r_rim = config.disc_radius_m;
  const double floor = std::max(0.0, in.depth_mm) * 1e-3;
  // The root end's lowest point below the surface: the disc rides with the opener.
  const double length = in.length_mm * 1e-3;
  const double diameter = in.diameter_mm * 1e-3;
  const double omega = std::max(1e-3, in.omega_radps);
  const double v = in.v_mps;
  const double theta_r = mc.release_after_lowest_deg * kRadPerDeg;
  const double dtheta = 1.0 / kStepsPerRad;
  const double dt = dtheta / omega;
  const double clamp_N = std::max(0.0, in.clamp_force_N);
  ReleaseOutcome out;

  // 0. Carried: the grip against the seedling's weight and accelerations.
  if (clamp_N < carry_grip_needed_N(config, in.length_mm, in.diameter_mm, omega)) {
    out.fell_in_carry = true;
    return out;
  }

  // The held seedling's geometry, relative to the hub: the lips at the rim at disc angle theta
  // (0 at the lowest point), the rod from them to the root end along the radius turned by the
  // seedling's own turn in the clamp (+ top forward), `protrusion` long. Both change when the
  // soil beats the grip, and the root's depth follows from them, so a seedling that turns or
  // slides reaches the soil where its new geometry puts it.
  double protrusion = mc.root_protrusion_mm * 1e-3;
  double slipped = 0.0;  // turned by slipping in the clamp, + top forward
  // The hub above the original surface: the root end's lowest point (untouched seedling) sits
  // root_clearance_mm above the floor, the disc riding with the opener.
  const double hub_height = r_rim + protrusion + mc.root_clearance_mm * 1e-3 - floor;
  auto radial = [](double a) { return std::array<double, 2>{-std::sin(a), -std::cos(a)}; };
  auto root_at = [&](double theta) {
    const auto rim = radial(theta), rod = radial(theta + slipped);
    return std::array<double, 2>{r_rim * rim[0] + protrusion * rod[0],
                                 hub_height + r_rim * rim[1] + protrusion * rod[1]};
  };
  // Depth of the root end below the surface, on the floor at most.
  auto burial = [&](double theta) { return std::clamp(-root_at(theta)[1], 0.0, floor); };
  // The opener leaves the furrow open; the returning soil has refilled a share of it where the
  // seedling goes in. The root holds in that soil only until the covering wheel: the length of
  // it in that soil, for a root end root_depth below the surface.
  const double backflow_level = mc.backflow_fill * floor;  // above the floor
  auto embedded = [&](double root_depth) {
    return std::max(0.0, backflow_level - (floor - root_depth));
  };

  // 1. Held: from where the root end reaches the surface to the release. Before the grip gives,
  // the lips turn with the seedling elastically: turning the stem in the disc's plane shears the
  // rubber under the contact in that plane (the faces do not compress), so the stiffness is the
  // rubber's shear law, tau = G gamma over the sheared layer h (Gent, Engineering with Rubber,
  // ch. 3: a thin layer in simple shear). A patch of area A (w long, d wide) on each of two faces
  // turned by phi moves a point at r by r phi: k = 2 G A (w^2 + d^2) / (12 h).
  const double entry = -std::acos(std::clamp((hub_height) / (r_rim + protrusion), -1.0, 1.0));
  const double held_length = held_length_m(mc, in.diameter_mm);
  const double grip_N = 2.0 * mc.lip_friction * clamp_N;  // both faces
  const double hold_Nm = grip_N * held_length / 4.0;      // mu N w / 2
  const double lip_Nm_per_rad =
      std::max(1e-6, lip_turning_stiffness_Nm_per_rad(mc, in.diameter_mm));
  double elastic = 0.0;  // the lips' elastic give, at the release
  for (double theta = entry; theta < theta_r; theta += dtheta) {
    const double b = embedded(burial(theta));
    if (b <= 0.0) continue;
    // The root end's ground velocity if the seedling moved with the lips: the machine's travel
    // and the disc's turn. Across the rod (+ where the turn grows) and along it (+ outwards).
    const double a = theta + slipped;
    const double ux = v - omega * (r_rim * std::cos(theta) + protrusion * std::cos(a));
    const double uy = omega * (r_rim * std::sin(theta) + protrusion * std::sin(a));
    const double u_across = -(ux * -std::cos(a) + uy * std::sin(a));  // + top forward
    const double u_along = ux * -std::sin(a) + uy * -std::cos(a);
    const double speed = std::hypot(u_across, u_along);
    if (speed <= 0.0) continue;
    // The soil resists the root's motion: plowed against it. Its share across the rod turns it
    // about the clamp; its share along the rod pushes it along the clamp.
    const double plow = backflow.plowing_force_N(diameter, b);
    const double arm = std::max(0.0, protrusion - (b - backflow.plowing_depth_m(diameter, b)));
    const double moment = plow * std::abs(u_across) / speed * arm * (u_across < 0.0 ? -1.0 : 1.0);
    elastic = std::clamp(moment, -hold_Nm, hold_Nm) / lip_Nm_per_rad;
    // Past the grip the root stays where the soil holds it while the clamp moves on.
    if (std::abs(moment) > hold_Nm) slipped += u_across * dt / protrusion;
    if (plow * std::abs(u_along) / speed > grip_N) {
      const double slide = -u_along * dt;  // the clamp moves on along the rod, the root stays
      protrusion = std::clamp(protrusion + slide, 0.01, length);
      out.clamp_slip_mm += slide * 1e3;
    }
  }
  const double turn = slipped + elastic;
  out.clamp_turn_deg = turn / kRadPerDeg;

  // 2. Released: the rod about its root end, (x, y) with y up from the soil surface.
  const double buried = burial(theta_r);
  const double b = embedded(buried);
  out.burial_mm = buried * 1e3;
  double phi = theta_r + turn;                // + top forward
  const double root_x = root_at(theta_r)[0];  // hub at x = 0 at release
  const double root_y = -buried;
  const double drag_N = mc.lip_friction * mc.residual_grip_share * clamp_N;
  const double phi_release = phi;
  for (double t = 0.0; t < 2.0 * std::numbers::pi / omega; t += dt) {
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
    if (drag_N > backflow.holding_force_N(diameter, b, lips_height)) phi += across * dt / s_c;
  }
  out.lip_drag_deg = (phi - phi_release) / kRadPerDeg;
  phi += in.scatter_deg * kRadPerDeg;

  // 3. Standing: the rod about its root end under its weight, the returned soil resisting, until
  // the covering wheel comes; then the firmed soil over the whole burial.
  const double mass = seedling_mass_kg(config, length, diameter);
  const double inertia = mass * length * length / 3.0;
  const double weight_arm_Nm = mass * kG * 0.5 * length;
  const double loose_Nm = backflow.holding_moment_Nm(diameter, b);
  const double cover_s =
      v > 1e-4 ? std::min(kLongestWait_s, mc.covering_wheel_behind_mm * 1e-3 / v) : kLongestWait_s;
  const double phi_standing = phi;
  double rate = 0.0;  // rad/s
  for (double t = 0.0; t < cover_s && std::abs(phi) < 0.5 * std::numbers::pi; t += kFallStep_s) {
    const double tipping = weight_arm_Nm * std::sin(phi);
    if (rate == 0.0 && std::abs(tipping) <= loose_Nm) break;  // it stands
    const double direction = rate != 0.0 ? std::copysign(1.0, rate) : std::copysign(1.0, phi);
    rate += (tipping - direction * loose_Nm) / inertia * kFallStep_s;
    if (rate * direction < 0.0) break;  // the soil has stopped it
    phi += rate * kFallStep_s;
  }
  out.fall_deg = (phi - phi_standing) / kRadPerDeg;
  const double covered_Nm = firmed.holding_moment_Nm(diameter, buried);
  if (std::abs(phi) >= 0.5 * std::numbers::pi ||
      weight_arm_Nm * std::abs(std::sin(phi)) > covered_Nm) {
    out.lodged = true;
    phi = std::copysign(90.0 * kRadPerDeg, phi);
  }
  out.tilt_deg = std::clamp(phi / kRadPerDeg, -90.0, 90.0);
  return out;
}

}  // namespace planter::sim
