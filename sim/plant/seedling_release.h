#pragma once
// How a seedling comes to stand in the furrow: its release, from mechanics (the paper, Sec. 2
// and Fig. 5: the root is buried while the leaves are still held; the disc pushes the top
// backwards, F', and the returning soil pushes the root forwards, F).
//
// The seedling is a rigid rod (its length, diameter and the paper's density 870.5 kg/m^3),
// radial in the disc with its root end beyond the rim, in the plane of the row. At 0.06 m/s
// and 0.3 rad/s the accelerations are a thousandth of g, so each instant is quasi-static: the
// rod goes where the forces on it balance. Three stages, integrated over the disc's angle:
//  1. Held: the root end follows the trochoid of radius R + protrusion at the actual v and
//     omega. Once below the surface it is dragged sideways through the soil (Broms' plowing
//     force, sim/soil/root_anchorage.h). The lips hold the seedling against turning with a
//     friction moment mu N w / 4 (N the clamp force, w = contact area / diameter the length
//     held, uniform pressure). When the soil's moment about the clamp is larger, the root
//     stays where the soil holds it and the seedling turns in the clamp (the paper, Sec. 4.3:
//     a small contact area lets the seedling deflect at the clamping point).
//  2. Released: the lips open past the lowest point. The leaves still between them are
//     dragged with the disc's surface by friction mu N_res (F'). When that is more than the
//     buried root can hold (Broms' free short pile, load at the lips' height), the seedling
//     turns about its root end with the lips; otherwise the lips slide over it. This lasts
//     until the rod's top leaves the disc's circle.
//  3. Standing: what the model leaves out is added as a scatter (crooked seedlings, the soil
//     settling, the covering wheel, the machine's vibration); then gravity about the root end
//     against the soil's moment capacity. A seedling whose weight's moment is larger lodges (lies
//     in the furrow, 90 deg). The covering wheel then firms the soil, and the tilt is final.
// The root's end goes no deeper than the furrow floor. Left out: the soil's elastic give (about
// a millimetre), the rod's bending, and the root's pull-out.
#include "sim/plant/plant_config.h"

namespace planter::sim {

struct ReleaseInput {
  double length_mm = 0, diameter_mm = 0;
  double v_mps = 0;          // ground speed at release
  double omega_radps = 0;    // disc speed at release
  double depth_mm = 0;       // furrow depth
  double clamp_force_N = 0;  // the lips' force on the seedling while held
  double scatter_deg = 0;    // what the stages leave out, added before it stands (+ top forward)
};

struct ReleaseOutcome {
  double tilt_deg = 0;        // after covering, + top forward (90: lodged)
  double clamp_turn_deg = 0;  // turned in the clamp while held (stage 1)
  double lip_drag_deg = 0;    // turned by the lips after release (stage 2)
  double burial_mm = 0;       // root end's depth below the surface
  bool lodged = false;
};

ReleaseOutcome release_seedling(const PlantConfig& config, const ReleaseInput& in);

}  // namespace planter::sim
